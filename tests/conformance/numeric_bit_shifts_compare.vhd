-- vams: stop 10 ns
--
-- ieee.numeric_bit's shifts, rotations, comparisons and logical operators: shift_left /
-- shift_right (arithmetic on signed: the sign fills), rotate_left / rotate_right, the
-- operators sll srl rol ror (srl logical on signed too, a negative count shifting the other
-- way), comparisons that are numeric across lengths and with natural and integer operands
-- (including numbers wider than the vector), and and/or/xor/not element by element.

LIBRARY ieee;  USE ieee.numeric_bit.ALL;

ENTITY tb_numeric_bit_shifts_compare IS
END ENTITY tb_numeric_bit_shifts_compare;

ARCHITECTURE test OF tb_numeric_bit_shifts_compare IS
BEGIN
  check : PROCESS IS
    VARIABLE u4 : unsigned(3 DOWNTO 0) := "1010";            -- 10
    VARIABLE u6 : unsigned(5 DOWNTO 0) := "000110";          -- 6
    VARIABLE u8 : unsigned(7 DOWNTO 0) := "11111111";        -- 255
    VARIABLE s_m7 : signed(3 DOWNTO 0) := "1001";            -- -7
    VARIABLE s_p3 : signed(3 DOWNTO 0) := "0011";            -- 3
    VARIABLE s8_m2 : signed(7 DOWNTO 0) := "11111110";       -- -2
    VARIABLE r4 : unsigned(3 DOWNTO 0);
    VARIABLE rs4 : signed(3 DOWNTO 0);
  BEGIN
    WAIT FOR 1 ns;
    -- Shifts and rotations of u4 = 1010 and s_m7 = 1001.
    r4 := shift_left(u4, 1);
    ASSERT r4 = "0100" REPORT "shift_left(1010, 1)" SEVERITY error;
    r4 := shift_left(u4, 7);                                 -- everything shifted out
    ASSERT r4 = "0000" REPORT "shift_left(1010, 7)" SEVERITY error;
    r4 := shift_right(u4, 2);
    ASSERT r4 = "0010" REPORT "shift_right unsigned" SEVERITY error;
    rs4 := shift_right(s_m7, 2);                             -- 1001 -> 1110 (sign fill)
    ASSERT rs4 = "1110" REPORT "shift_right signed" SEVERITY error;
    rs4 := shift_right(s_p3, 1);                             -- 0011 -> 0001
    ASSERT rs4 = "0001" REPORT "shift_right positive signed" SEVERITY error;
    rs4 := shift_left(s_m7, 1);                              -- 1001 -> 0010
    ASSERT rs4 = "0010" REPORT "shift_left signed" SEVERITY error;
    r4 := rotate_left(u4, 1);
    ASSERT r4 = "0101" REPORT "rotate_left" SEVERITY error;
    r4 := rotate_left(u4, 4);                                -- a whole turn
    ASSERT r4 = "1010" REPORT "rotate_left by the length" SEVERITY error;
    r4 := rotate_right(u4, 3);                               -- 1010 -> 0101
    ASSERT r4 = "0101" REPORT "rotate_right" SEVERITY error;
    rs4 := rotate_right(s_m7, 1);                            -- 1001 -> 1100
    ASSERT rs4 = "1100" REPORT "rotate_right signed" SEVERITY error;
    r4 := u4 SLL 2;
    ASSERT r4 = "1000" REPORT "sll" SEVERITY error;
    r4 := u4 SRL 1;
    ASSERT r4 = "0101" REPORT "srl" SEVERITY error;
    r4 := u4 SLL (-1);                                       -- a negative count: srl 1
    ASSERT r4 = "0101" REPORT "sll -1" SEVERITY error;
    rs4 := s_m7 SRL 1;                                       -- logical: 0100
    ASSERT rs4 = "0100" REPORT "srl signed" SEVERITY error;
    rs4 := s_m7 SLL (-2);                                    -- logical too: 0010
    ASSERT rs4 = "0010" REPORT "sll -2 signed" SEVERITY error;
    r4 := u4 ROL 3;                                          -- 1010 -> 0101
    ASSERT r4 = "0101" REPORT "rol" SEVERITY error;
    r4 := u4 ROR 1;
    ASSERT r4 = "0101" REPORT "ror" SEVERITY error;
    rs4 := s_m7 ROL 1;                                       -- 1001 -> 0011
    ASSERT rs4 = "0011" REPORT "rol signed" SEVERITY error;

    -- Comparisons: numeric across lengths, with naturals and integers on either side.
    ASSERT u4 > u6 AND u6 < u4 AND NOT (u4 = u6) AND u4 /= u6
      REPORT "10 vs 6 across lengths" SEVERITY error;
    ASSERT u6 = "0110" AND u6 = "00000110" AND u6 >= "110" AND u6 <= "0110"
      REPORT "6 vs literals of other lengths" SEVERITY error;
    ASSERT u4 > 9 AND u4 < 11 AND u4 = 10 AND u4 /= 3 AND u4 >= 10 AND u4 <= 10
      REPORT "unsigned vs natural" SEVERITY error;
    ASSERT 10 = u4 AND 9 < u4 AND NOT (11 <= u4) AND 11 > u4 AND 10 >= u4 AND 3 /= u4
      REPORT "natural vs unsigned" SEVERITY error;
    ASSERT u8 > 254 AND u8 < 1000 AND u8 /= 511 AND NOT (u8 = 511)
      REPORT "255 vs naturals wider than 8 bits" SEVERITY error;
    ASSERT s_m7 < 0 AND s_m7 = -7 AND s_m7 >= -7 AND s_m7 > -8 AND s_m7 <= -7
      REPORT "signed vs integer" SEVERITY error;
    ASSERT -8 < s_m7 AND 0 > s_m7 AND -7 = s_m7 AND -6 /= s_m7
      REPORT "integer vs signed" SEVERITY error;
    ASSERT s_m7 > -1000 AND s_m7 < 1000 AND s_m7 /= -1000
      REPORT "signed vs integers wider than 4 bits" SEVERITY error;
    ASSERT s_m7 < s_p3 AND s_p3 > s_m7 AND s8_m2 > s_m7 AND s_m7 < s8_m2
      REPORT "signed vs signed, negatives across lengths" SEVERITY error;
    ASSERT s8_m2 = "1110" AND s8_m2 = "10" AND s8_m2 /= "0110"
      REPORT "-2 vs sign-extended literals" SEVERITY error;

    -- Logical operators, element by element.
    r4 := u4 AND "0110";
    ASSERT r4 = "0010" REPORT "and" SEVERITY error;
    r4 := u4 OR "0101";
    ASSERT r4 = "1111" REPORT "or" SEVERITY error;
    r4 := u4 XOR "1111";
    ASSERT r4 = "0101" REPORT "xor" SEVERITY error;
    r4 := u4 NAND "1110";
    ASSERT r4 = "0101" REPORT "nand" SEVERITY error;
    r4 := u4 NOR "0001";
    ASSERT r4 = "0100" REPORT "nor" SEVERITY error;
    r4 := u4 XNOR "1000";
    ASSERT r4 = "1101" REPORT "xnor" SEVERITY error;
    r4 := NOT u4;
    ASSERT r4 = "0101" REPORT "not" SEVERITY error;
    rs4 := NOT s_m7;                                         -- 0110
    ASSERT rs4 = "0110" REPORT "not signed" SEVERITY error;
    rs4 := s_m7 AND s_p3;                                    -- 0001
    ASSERT rs4 = "0001" REPORT "and signed" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
