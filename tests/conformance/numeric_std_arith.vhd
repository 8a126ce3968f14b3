-- vams: stop 10 ns
--
-- ieee.numeric_std: unsigned and signed arithmetic wrapping at the result length (carry out
-- of "+", borrow of "-", overflow of signed), "*" giving the sum of the lengths, "/", "rem"
-- and "mod" of unsigned and signed operands (the signs of rem and mod), resize (sign
-- extension, and the sign bit kept when a signed shrinks), to_integer / to_unsigned /
-- to_signed round trips over the whole 8-bit range, the shift and rotate functions and
-- operators, comparisons with integers, std_match, and an 'X' operand giving all 'X'.
-- Expected values are worked out by hand in the comments.

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;  USE ieee.numeric_std.ALL;

ENTITY tb_numeric_std_arith IS
END ENTITY tb_numeric_std_arith;

ARCHITECTURE test OF tb_numeric_std_arith IS
  FUNCTION all_x ( v : unsigned ) RETURN boolean IS
  BEGIN
    FOR i IN v'RANGE LOOP
      IF v(i) /= 'X' THEN
        RETURN false;
      END IF;
    END LOOP;
    RETURN true;
  END FUNCTION all_x;
BEGIN
  check : PROCESS IS
    VARIABLE a : unsigned(7 DOWNTO 0) := "11111111";         -- 255
    VARIABLE b : unsigned(7 DOWNTO 0) := "00000001";         -- 1
    VARIABLE c : unsigned(7 DOWNTO 0) := "01100100";         -- 100
    VARIABLE d : unsigned(7 DOWNTO 0) := "00000111";         -- 7
    VARIABLE u4 : unsigned(3 DOWNTO 0) := "1010";            -- 10
    VARIABLE ux : unsigned(3 DOWNTO 0) := "10X1";
    VARIABLE s_min : signed(7 DOWNTO 0) := "10000000";       -- -128
    VARIABLE s_m7 : signed(3 DOWNTO 0) := "1001";            -- -7
    VARIABLE s_p7 : signed(3 DOWNTO 0) := "0111";            -- 7
    VARIABLE s_p2 : signed(3 DOWNTO 0) := "0010";            -- 2
    VARIABLE s_m2 : signed(3 DOWNTO 0) := "1110";            -- -2
    VARIABLE s_p3 : signed(3 DOWNTO 0) := "0011";            -- 3
    VARIABLE r4 : unsigned(3 DOWNTO 0);
    VARIABLE r8 : unsigned(7 DOWNTO 0);
    VARIABLE rs4 : signed(3 DOWNTO 0);
    VARIABLE rs8 : signed(7 DOWNTO 0);
    VARIABLE v4 : std_logic_vector(3 DOWNTO 0) := "1-0L";
  BEGIN
    WAIT FOR 1 ns;
    -- "+" and "-" wrap at the longer operand's length.
    r8 := a + b;                                             -- 255 + 1 = 256 -> 0
    ASSERT to_integer(r8) = 0 REPORT "255 + 1 carry" SEVERITY error;
    r8 := a + 1;
    ASSERT to_integer(r8) = 0 REPORT "255 + 1 (natural)" SEVERITY error;
    r4 := u4 + 6;                                            -- 16 -> 0
    ASSERT r4 = "0000" REPORT "1010 + 6" SEVERITY error;
    r8 := b - a;                                             -- 1 - 255 = -254 -> 2
    ASSERT to_integer(r8) = 2 REPORT "1 - 255 borrow" SEVERITY error;
    r8 := c + u4;                                            -- 100 + 10, 8 bits
    ASSERT to_integer(r8) = 110 REPORT "8-bit + 4-bit" SEVERITY error;
    rs8 := s_min - 1;                                        -- -129 -> 127
    ASSERT to_integer(rs8) = 127 REPORT "-128 - 1 overflow" SEVERITY error;
    rs4 := s_m7 + s_p2;                                      -- -5
    ASSERT to_integer(rs4) = -5 REPORT "-7 + 2" SEVERITY error;
    rs4 := "-"(s_m2);                                        -- 2 (unary minus as a call)
    ASSERT rs4 = "0010" REPORT "-(-2)" SEVERITY error;
    rs4 := "abs"(s_m7);                                      -- 7
    ASSERT rs4 = "0111" REPORT "abs(-7)" SEVERITY error;

    -- "*": the sum of the lengths (twice the vector's with a number).
    r8 := u4 * u4;                                           -- 100
    ASSERT to_integer(r8) = 100 REPORT "10 * 10" SEVERITY error;
    r8 := u4 * 3;                                            -- 30
    ASSERT to_integer(r8) = 30 REPORT "10 * 3" SEVERITY error;
    rs8 := s_m7 * s_p3;                                      -- -21 = 11101011
    ASSERT rs8 = "11101011" REPORT "-7 * 3" SEVERITY error;
    rs8 := s_m7 * s_m2;                                      -- 14
    ASSERT to_integer(rs8) = 14 REPORT "-7 * -2" SEVERITY error;

    -- "/", "rem", "mod": truncation toward zero, rem with the dividend's sign, mod with the
    -- divisor's.
    r8 := c / d;                                             -- 100 / 7 = 14
    ASSERT to_integer(r8) = 14 REPORT "100 / 7" SEVERITY error;
    r8 := c REM d;                                           -- 2
    ASSERT to_integer(r8) = 2 REPORT "100 rem 7" SEVERITY error;
    r8 := c MOD d;                                           -- 2
    ASSERT to_integer(r8) = 2 REPORT "100 mod 7" SEVERITY error;
    r8 := c / 7;                                             -- 14 (natural divisor)
    ASSERT to_integer(r8) = 14 REPORT "100 / 7 (natural)" SEVERITY error;
    r8 := c / 300;                                           -- 0: 300 does not fit 8 bits
    ASSERT to_integer(r8) = 0 REPORT "100 / 300" SEVERITY error;
    rs4 := s_m7 / s_p2;                                      -- -3
    ASSERT to_integer(rs4) = -3 REPORT "-7 / 2" SEVERITY error;
    rs4 := s_m7 REM s_p2;                                    -- -1
    ASSERT to_integer(rs4) = -1 REPORT "-7 rem 2" SEVERITY error;
    rs4 := s_m7 MOD s_p2;                                    -- 1
    ASSERT to_integer(rs4) = 1 REPORT "-7 mod 2" SEVERITY error;
    rs4 := s_p7 REM s_m2;                                    -- 1
    ASSERT to_integer(rs4) = 1 REPORT "7 rem -2" SEVERITY error;
    rs4 := s_p7 MOD s_m2;                                    -- -1
    ASSERT to_integer(rs4) = -1 REPORT "7 mod -2" SEVERITY error;
    rs4 := s_p7 / (-2);                                      -- -3 (integer divisor)
    ASSERT to_integer(rs4) = -3 REPORT "7 / -2" SEVERITY error;

    -- resize: sign extension, and a shrinking signed keeps its sign bit.
    rs8 := resize(s_m7, 8);                                  -- 11111001
    ASSERT rs8 = "11111001" REPORT "resize(-7, 8)" SEVERITY error;
    rs8 := resize(s_p7, 8);                                  -- 00000111
    ASSERT rs8 = "00000111" REPORT "resize(7, 8)" SEVERITY error;
    rs8 := "01111111";                                       -- 127
    rs4 := resize(rs8, 4);                                   -- '0' & "111" = 7
    ASSERT rs4 = "0111" REPORT "resize(127, 4)" SEVERITY error;
    rs8 := "10000001";                                       -- -127
    rs4 := resize(rs8, 4);                                   -- '1' & "001" = -7
    ASSERT rs4 = "1001" REPORT "resize(-127, 4)" SEVERITY error;
    r8 := "11110000";
    r4 := resize(r8, 4);                                     -- low bits 0000
    ASSERT r4 = "0000" REPORT "resize(unsigned 240, 4)" SEVERITY error;
    r8 := resize(u4, 8);                                     -- 00001010
    ASSERT r8 = "00001010" REPORT "resize(unsigned 10, 8)" SEVERITY error;

    -- Round trips over the whole 8-bit ranges.
    FOR i IN 0 TO 255 LOOP
      r8 := to_unsigned(i, 8);
      ASSERT to_integer(r8) = i REPORT "to_unsigned/to_integer " & integer'IMAGE(i) SEVERITY error;
    END LOOP;
    FOR i IN -128 TO 127 LOOP
      rs8 := to_signed(i, 8);
      ASSERT to_integer(rs8) = i REPORT "to_signed/to_integer " & integer'IMAGE(i) SEVERITY error;
    END LOOP;
    rs8 := to_signed(-3, 8);                                 -- 11111101
    ASSERT rs8 = "11111101" REPORT "to_signed(-3, 8)" SEVERITY error;
    r4 := to_unsigned(20, 4);                                -- 20 mod 16 = 4
    ASSERT r4 = "0100" REPORT "to_unsigned(20, 4)" SEVERITY error;

    -- Shifts and rotations (u4 = 1010).
    r4 := shift_left(u4, 1);
    ASSERT r4 = "0100" REPORT "shift_left" SEVERITY error;
    r4 := shift_right(u4, 2);
    ASSERT r4 = "0010" REPORT "shift_right unsigned" SEVERITY error;
    rs4 := shift_right(s_m7, 2);                             -- 1001 -> 1110 (sign fill)
    ASSERT rs4 = "1110" REPORT "shift_right signed" SEVERITY error;
    r4 := rotate_left(u4, 1);
    ASSERT r4 = "0101" REPORT "rotate_left" SEVERITY error;
    r4 := rotate_right(u4, 3);                               -- 1010 -> 0101
    ASSERT r4 = "0101" REPORT "rotate_right" SEVERITY error;
    r4 := u4 SLL 2;
    ASSERT r4 = "1000" REPORT "sll" SEVERITY error;
    rs4 := s_m7 SRL 1;                                       -- logical: 0100
    ASSERT rs4 = "0100" REPORT "srl signed" SEVERITY error;
    r4 := u4 ROR 1;
    ASSERT r4 = "0101" REPORT "ror" SEVERITY error;

    -- Comparisons with integers.
    ASSERT u4 > 9 AND u4 < 11 AND u4 = 10 AND u4 /= 3 AND u4 >= 10 AND u4 <= 10
      REPORT "unsigned vs natural" SEVERITY error;
    ASSERT 10 = u4 AND 9 < u4 AND NOT (11 <= u4) REPORT "natural vs unsigned" SEVERITY error;
    ASSERT s_m7 < 0 AND s_m7 = -7 AND s_m7 >= -7 AND s_m7 > -8 AND -8 < s_m7
      REPORT "signed vs integer" SEVERITY error;
    ASSERT a > 254 AND a < 1000 REPORT "255 vs wider integers" SEVERITY error;

    -- Metavalues: arithmetic gives 'X's, to_integer 0, comparisons false.
    r4 := ux + 1;
    ASSERT all_x(r4) REPORT "10X1 + 1 is not XXXX" SEVERITY error;
    r4 := ux + u4;
    ASSERT all_x(r4) REPORT "10X1 + 1010 is not XXXX" SEVERITY error;
    ASSERT to_integer(ux) = 0 REPORT "to_integer(10X1) /= 0" SEVERITY error;
    ASSERT NOT (ux = 11) AND NOT (ux < 100) AND ux /= 11 REPORT "10X1 vs integer" SEVERITY error;

    -- std_match and the logical operators.
    ASSERT std_match(v4, "1100") AND std_match(v4, "1000") AND NOT std_match(v4, "0100")
      REPORT "std_match" SEVERITY error;
    r4 := u4 AND "0110";
    ASSERT r4 = "0010" REPORT "and" SEVERITY error;
    r4 := NOT u4;
    ASSERT r4 = "0101" REPORT "not" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
