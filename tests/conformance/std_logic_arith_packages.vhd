-- vams: stop 100 ns
--
-- The de-facto packages ieee.std_logic_arith, std_logic_unsigned and std_logic_signed: a
-- counter written `cnt <= cnt + "0001"` and `cnt + 1` on std_logic_vector (wrapping at
-- 16), the result lengths (the longer operand for "+", the sum for "*"), comparisons with
-- integers, conv_integer, conv_std_logic_vector, conv_signed/conv_unsigned, ext/sxt,
-- shl/shr, an operand holding 'X' giving all 'X', and std_logic_signed's two's complement
-- reading of the same vectors (in the entity std_logic_signed_checks, instantiated by the
-- testbench, since one design unit cannot use both vector packages).

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;  USE ieee.std_logic_arith.ALL;
USE ieee.std_logic_signed.ALL;

ENTITY std_logic_signed_checks IS
END ENTITY std_logic_signed_checks;

ARCHITECTURE test OF std_logic_signed_checks IS
BEGIN
  check : PROCESS IS
    VARIABLE a : std_logic_vector(3 DOWNTO 0) := "1110";     -- -2
    VARIABLE b : std_logic_vector(3 DOWNTO 0) := "1000";     -- -8 (8 if unsigned)
    VARIABLE c : std_logic_vector(3 DOWNTO 0) := "0011";     -- 3
    VARIABLE x : std_logic_vector(3 DOWNTO 0) := "X001";
    VARIABLE r4 : std_logic_vector(3 DOWNTO 0);
    VARIABLE r8 : std_logic_vector(7 DOWNTO 0);
  BEGIN
    WAIT FOR 1 ns;
    ASSERT conv_integer(a) = -2 REPORT "signed conv_integer(1110) /= -2" SEVERITY error;
    ASSERT a < 0 AND a > -3 AND a = -2 AND a /= 14 REPORT "signed a vs integer" SEVERITY error;
    ASSERT b < 7 REPORT "signed 1000 < 7 (-8 < 7)" SEVERITY error;
    ASSERT -9 < b AND -8 <= b AND 0 > b REPORT "integer vs signed" SEVERITY error;
    r4 := a + 1;                                             -- -2 + 1 = -1
    ASSERT r4 = "1111" REPORT "signed a + 1" SEVERITY error;
    r4 := a + c;                                             -- -2 + 3 = 1
    ASSERT r4 = "0001" REPORT "signed a + c" SEVERITY error;
    r4 := b - 1;                                             -- -8 - 1 wraps to 7
    ASSERT r4 = "0111" REPORT "signed b - 1 wrap" SEVERITY error;
    r4 := "-"(a);                                            -- 2
    ASSERT r4 = "0010" REPORT "signed -a" SEVERITY error;
    r4 := "abs"(a);                                          -- 2
    ASSERT r4 = "0010" REPORT "signed abs a" SEVERITY error;
    r4 := "-"(b);                                            -- -(-8) stays -8 in 4 bits
    ASSERT r4 = "1000" REPORT "signed -b" SEVERITY error;
    r8 := a * c;                                             -- -6 in 8 bits
    ASSERT r8 = "11111010" REPORT "signed a * c" SEVERITY error;
    r4 := shr(b, "01");                                      -- sign fill: 1100
    ASSERT r4 = "1100" REPORT "signed shr" SEVERITY error;
    r4 := shl(c, "10");                                      -- 1100
    ASSERT r4 = "1100" REPORT "signed shl" SEVERITY error;
    r4 := x + 1;
    ASSERT r4 = "XXXX" REPORT "signed X + 1" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;  USE ieee.std_logic_arith.ALL;
USE ieee.std_logic_unsigned.ALL;

ENTITY tb_std_logic_arith_packages IS
END ENTITY tb_std_logic_arith_packages;

ARCHITECTURE test OF tb_std_logic_arith_packages IS
  SIGNAL clk : std_logic := '0';
  SIGNAL cnt : std_logic_vector(3 DOWNTO 0) := "1101";       -- 13
  SIGNAL cnt_i : std_logic_vector(3 DOWNTO 0) := "1110";     -- 14
BEGIN
  signed_checks : ENTITY work.std_logic_signed_checks;

  clock : PROCESS IS
  BEGIN
    FOR i IN 1 TO 4 LOOP                                     -- rising edges at 0, 10, 20, 30 ns
      clk <= '1';
      WAIT FOR 5 ns;
      clk <= '0';
      WAIT FOR 5 ns;
    END LOOP;
    WAIT;
  END PROCESS clock;

  counter : PROCESS (clk) IS
  BEGIN
    IF rising_edge(clk) THEN
      cnt <= cnt + "0001";
      cnt_i <= cnt_i + 1;
    END IF;
  END PROCESS counter;

  check : PROCESS IS
    VARIABLE v4 : std_logic_vector(3 DOWNTO 0) := "1011";    -- 11
    VARIABLE a8 : std_logic_vector(7 DOWNTO 0) := "11110000"; -- 240
    VARIABLE x4 : std_logic_vector(3 DOWNTO 0) := "10X1";
    VARIABLE r4 : std_logic_vector(3 DOWNTO 0);
    VARIABLE r6 : std_logic_vector(5 DOWNTO 0);
    VARIABLE r8 : std_logic_vector(7 DOWNTO 0);
    VARIABLE u : unsigned(3 DOWNTO 0) := "1111";             -- 15
    VARIABLE s : signed(3 DOWNTO 0) := "1000";               -- -8
    VARIABLE s3 : signed(3 DOWNTO 0) := "0011";              -- 3
    VARIABLE rs4 : signed(3 DOWNTO 0);
    VARIABLE rs5 : signed(4 DOWNTO 0);
    VARIABLE rs8 : signed(7 DOWNTO 0);
    VARIABLE ru2 : unsigned(1 DOWNTO 0);
  BEGIN
    WAIT FOR 50 ns;
    -- 13 + 4 = 17 wraps to 1; 14 + 4 = 18 wraps to 2.
    ASSERT cnt = "0001" REPORT "cnt + ""0001"" counter" SEVERITY error;
    ASSERT cnt_i = "0010" REPORT "cnt + 1 counter" SEVERITY error;

    -- std_logic_unsigned on std_logic_vector.
    ASSERT conv_integer(v4) = 11 REPORT "conv_integer(1011) /= 11" SEVERITY error;
    ASSERT v4 > 10 AND v4 < 12 AND v4 = 11 AND v4 /= 3 REPORT "v4 vs integer" SEVERITY error;
    ASSERT 11 <= v4 AND 12 > v4 AND 11 >= v4 REPORT "integer vs v4" SEVERITY error;
    r8 := a8 + v4;                                           -- 240 + 11 = 251, 8 bits
    ASSERT r8 = "11111011" REPORT "8-bit + 4-bit" SEVERITY error;
    r4 := "0000";
    r4 := r4 - 1;                                            -- 0 - 1 wraps to 15
    ASSERT r4 = "1111" REPORT "0000 - 1" SEVERITY error;
    r4 := v4 - "1100";                                       -- 11 - 12 wraps to 15
    ASSERT r4 = "1111" REPORT "1011 - 1100" SEVERITY error;
    r6 := v4 * "11";                                         -- 11 * 3 = 33 = 100001, 4 + 2 bits
    ASSERT r6 = "100001" REPORT "1011 * 11" SEVERITY error;
    r4 := shl(v4, "01");                                     -- 0110
    ASSERT r4 = "0110" REPORT "shl" SEVERITY error;
    r4 := shr(v4, "10");                                     -- 0010
    ASSERT r4 = "0010" REPORT "shr" SEVERITY error;
    r4 := x4 + "0001";
    ASSERT r4 = "XXXX" REPORT "10X1 + 0001 is not XXXX" SEVERITY error;
    r4 := x4 + 1;
    ASSERT r4 = "XXXX" REPORT "10X1 + 1 is not XXXX" SEVERITY error;
    ASSERT conv_integer(x4) = 0 REPORT "conv_integer(10X1) /= 0" SEVERITY error;

    -- std_logic_arith's conversions.
    r4 := conv_std_logic_vector(11, 4);
    ASSERT r4 = "1011" REPORT "conv_std_logic_vector(11, 4)" SEVERITY error;
    r4 := conv_std_logic_vector(-3, 4);                      -- two's complement 1101
    ASSERT r4 = "1101" REPORT "conv_std_logic_vector(-3, 4)" SEVERITY error;
    r4 := conv_std_logic_vector(20, 4);                      -- 20 mod 16 = 4
    ASSERT r4 = "0100" REPORT "conv_std_logic_vector(20, 4)" SEVERITY error;
    r6 := ext(v4, 6);
    ASSERT r6 = "001011" REPORT "ext" SEVERITY error;
    r6 := sxt(v4, 6);
    ASSERT r6 = "111011" REPORT "sxt" SEVERITY error;

    -- std_logic_arith's own types.
    ASSERT conv_integer(u) = 15 AND conv_integer(s) = -8 REPORT "conv_integer" SEVERITY error;
    rs5 := u + s;                                            -- 15 + -8 = 7, 5 bits (u gets a sign bit)
    ASSERT conv_integer(rs5) = 7 REPORT "unsigned + signed" SEVERITY error;
    rs8 := s * s3;                                           -- -24 in 8 bits
    ASSERT conv_integer(rs8) = -24 REPORT "signed * signed" SEVERITY error;
    rs4 := s + 1;                                            -- -7
    ASSERT conv_integer(rs4) = -7 REPORT "signed + 1" SEVERITY error;
    rs4 := "abs"(s3);
    ASSERT conv_integer(rs4) = 3 REPORT "abs" SEVERITY error;
    rs8 := conv_signed(s, 8);                                -- sign extension
    ASSERT conv_integer(rs8) = -8 REPORT "conv_signed(s, 8)" SEVERITY error;
    ru2 := conv_unsigned(u, 2);                              -- low bits: 11
    ASSERT conv_integer(ru2) = 3 REPORT "conv_unsigned(u, 2)" SEVERITY error;
    ASSERT s < 0 AND u > 14 AND s < u AND u > s3 REPORT "mixed comparisons" SEVERITY error;
    ASSERT NOT (s > u) AND s3 >= 3 AND -8 = s REPORT "mixed comparisons 2" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
