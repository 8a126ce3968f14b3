-- vams: stop 10 ns
--
-- ieee.numeric_bit (IEEE 1076.3), the bit-based twin of numeric_std, as the textbooks use
-- it: unsigned and signed arithmetic wrapping at the result length (carry out of "+",
-- borrow of "-", signed overflow), negative numbers, unary minus and abs, "*" giving the
-- sum of the lengths, "/", "rem" and "mod" of unsigned and signed operands (the signs of
-- rem and mod), to_integer / to_unsigned / to_signed round trips over whole ranges, and
-- resize (sign extension of signed, zero extension of unsigned, and what each keeps when
-- it shrinks). Expected values are worked out by hand in the comments.

LIBRARY ieee;  USE ieee.numeric_bit.ALL;

ENTITY tb_numeric_bit_arith IS
END ENTITY tb_numeric_bit_arith;

ARCHITECTURE test OF tb_numeric_bit_arith IS
BEGIN
  check : PROCESS IS
    VARIABLE a : unsigned(7 DOWNTO 0) := "11111111";         -- 255
    VARIABLE b : unsigned(7 DOWNTO 0) := "00000001";         -- 1
    VARIABLE c : unsigned(7 DOWNTO 0) := "01100100";         -- 100
    VARIABLE d : unsigned(7 DOWNTO 0) := "00000111";         -- 7
    VARIABLE u4 : unsigned(3 DOWNTO 0) := "1010";            -- 10
    VARIABLE word : unsigned(0 TO 15) := X"00FF";            -- 255, ascending range
    VARIABLE s_min : signed(7 DOWNTO 0) := "10000000";       -- -128
    VARIABLE s_max : signed(7 DOWNTO 0) := "01111111";       -- 127
    VARIABLE s_m7 : signed(3 DOWNTO 0) := "1001";            -- -7
    VARIABLE s_p7 : signed(3 DOWNTO 0) := "0111";            -- 7
    VARIABLE s_p2 : signed(3 DOWNTO 0) := "0010";            -- 2
    VARIABLE s_m2 : signed(3 DOWNTO 0) := "1110";            -- -2
    VARIABLE s_p3 : signed(3 DOWNTO 0) := "0011";            -- 3
    VARIABLE s_m1 : signed(1 DOWNTO 0) := "11";              -- -1, 2 bits
    VARIABLE r4 : unsigned(3 DOWNTO 0);
    VARIABLE r8 : unsigned(7 DOWNTO 0);
    VARIABLE r16 : unsigned(15 DOWNTO 0);
    VARIABLE rs4 : signed(3 DOWNTO 0);
    VARIABLE rs8 : signed(7 DOWNTO 0);
    VARIABLE rs10 : signed(9 DOWNTO 0);
    VARIABLE rs12 : signed(11 DOWNTO 0);
    VARIABLE bv : bit_vector(7 DOWNTO 0);
    VARIABLE checked : natural := 0;
  BEGIN
    WAIT FOR 1 ns;
    -- "+" and "-" wrap at the longer operand's length: the carry out is lost.
    r8 := a + b;                                             -- 255 + 1 = 256 -> 0
    ASSERT r8 = "00000000" REPORT "255 + 1 carry" SEVERITY error;
    r8 := a + 1;
    ASSERT to_integer(r8) = 0 REPORT "255 + 1 (natural)" SEVERITY error;
    r8 := 3 + a;                                             -- 258 -> 2
    ASSERT to_integer(r8) = 2 REPORT "3 + 255 (natural first)" SEVERITY error;
    r8 := "01111111" + b;                                    -- a carry through 7 bits
    ASSERT r8 = "10000000" REPORT "127 + 1 ripple" SEVERITY error;
    r4 := u4 + 6;                                            -- 16 -> 0
    ASSERT r4 = "0000" REPORT "1010 + 6" SEVERITY error;
    r8 := b - a;                                             -- 1 - 255 = -254 -> 2
    ASSERT to_integer(r8) = 2 REPORT "1 - 255 borrow" SEVERITY error;
    r8 := 0 - b;                                             -- -1 -> 255
    ASSERT r8 = "11111111" REPORT "0 - 1 borrow" SEVERITY error;
    r8 := c + u4;                                            -- 100 + 10, 8 bits
    ASSERT to_integer(r8) = 110 REPORT "8-bit + 4-bit" SEVERITY error;
    r16 := word + 1;                                         -- ascending operand: 256
    ASSERT to_integer(r16) = 256 REPORT "unsigned(0 to 15) + 1" SEVERITY error;
    rs8 := s_min - 1;                                        -- -129 -> 127
    ASSERT to_integer(rs8) = 127 REPORT "-128 - 1 overflow" SEVERITY error;
    rs8 := s_max + 1;                                        -- 128 -> -128
    ASSERT rs8 = "10000000" REPORT "127 + 1 overflow" SEVERITY error;
    rs4 := s_m7 + s_p2;                                      -- -5
    ASSERT to_integer(rs4) = -5 REPORT "-7 + 2" SEVERITY error;
    rs4 := s_m2 + s_m2;                                      -- -4 = 1100
    ASSERT rs4 = "1100" REPORT "-2 + -2" SEVERITY error;
    rs4 := s_p2 - s_p7;                                      -- -5 = 1011
    ASSERT rs4 = "1011" REPORT "2 - 7" SEVERITY error;
    rs4 := s_p3 + s_m1;                                      -- the 2-bit -1 sign-extends: 2
    ASSERT to_integer(rs4) = 2 REPORT "3 + (-1 in 2 bits)" SEVERITY error;
    rs4 := s_m7 + (-1);                                      -- -8
    ASSERT to_integer(rs4) = -8 REPORT "-7 + -1 (integer)" SEVERITY error;
    rs4 := 5 - s_m2;                                         -- 7
    ASSERT to_integer(rs4) = 7 REPORT "5 - -2 (integer first)" SEVERITY error;
    rs4 := -s_m2;                                            -- 2
    ASSERT rs4 = "0010" REPORT "-(-2)" SEVERITY error;
    rs4 := -s_p7;                                            -- -7
    ASSERT rs4 = "1001" REPORT "-(7)" SEVERITY error;
    rs4 := ABS s_m7;                                         -- 7
    ASSERT rs4 = "0111" REPORT "abs(-7)" SEVERITY error;
    rs4 := ABS s_p3;                                         -- 3
    ASSERT rs4 = "0011" REPORT "abs(3)" SEVERITY error;

    -- "*": the sum of the lengths (twice the vector's with a number).
    r8 := u4 * u4;                                           -- 100
    ASSERT to_integer(r8) = 100 REPORT "10 * 10" SEVERITY error;
    r8 := u4 * 3;                                            -- 30
    ASSERT to_integer(r8) = 30 REPORT "10 * 3" SEVERITY error;
    r16 := a * a;                                            -- 65025 = FE01
    ASSERT r16 = X"FE01" REPORT "255 * 255" SEVERITY error;
    rs8 := s_m7 * s_p3;                                      -- -21 = 11101011
    ASSERT rs8 = "11101011" REPORT "-7 * 3" SEVERITY error;
    rs8 := s_m7 * s_m2;                                      -- 14
    ASSERT to_integer(rs8) = 14 REPORT "-7 * -2" SEVERITY error;
    rs8 := s_p7 * (-3);                                      -- -21
    ASSERT to_integer(rs8) = -21 REPORT "7 * -3 (integer)" SEVERITY error;
    rs10 := rs8 * s_m1;                                      -- -21 * -1 = 21, 10 bits
    ASSERT rs10 = "0000010101" REPORT "-21 * -1" SEVERITY error;

    -- "/", "rem", "mod": truncation toward zero, rem with the dividend's sign, mod with
    -- the divisor's.
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
    r4 := 77 REM u4;                                         -- 7
    ASSERT to_integer(r4) = 7 REPORT "77 rem 10" SEVERITY error;
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
    rs4 := s_m7 MOD s_m2;                                    -- -1
    ASSERT to_integer(rs4) = -1 REPORT "-7 mod -2" SEVERITY error;
    rs4 := s_p7 / (-2);                                      -- -3 (integer divisor)
    ASSERT to_integer(rs4) = -3 REPORT "7 / -2" SEVERITY error;
    rs4 := (-6) MOD s_p7;                                    -- 1
    ASSERT to_integer(rs4) = 1 REPORT "-6 mod 7 (integer first)" SEVERITY error;

    -- Round trips over the whole 8-bit ranges, and the wrap of an integer too large.
    FOR i IN 0 TO 255 LOOP
      r8 := to_unsigned(i, 8);
      ASSERT to_integer(r8) = i REPORT "to_unsigned/to_integer " & integer'IMAGE(i) SEVERITY error;
      checked := checked + 1;
    END LOOP;
    FOR i IN -128 TO 127 LOOP
      rs8 := to_signed(i, 8);
      ASSERT to_integer(rs8) = i REPORT "to_signed/to_integer " & integer'IMAGE(i) SEVERITY error;
      checked := checked + 1;
    END LOOP;
    ASSERT checked = 512 REPORT "the round trip loops did not run" SEVERITY error;
    rs8 := to_signed(-3, 8);                                 -- 11111101
    ASSERT rs8 = "11111101" REPORT "to_signed(-3, 8)" SEVERITY error;
    rs12 := to_signed(-1000, 12);                            -- 4096 - 1000 = 3096 = C18
    ASSERT bit_vector(rs12) = X"C18" REPORT "to_signed(-1000, 12)" SEVERITY error;
    r4 := to_unsigned(20, 4);                                -- 20 mod 16 = 4
    ASSERT r4 = "0100" REPORT "to_unsigned(20, 4)" SEVERITY error;
    r16 := to_unsigned(51966, 16);                           -- CAFE
    ASSERT bit_vector(r16) = X"CAFE" REPORT "to_unsigned(51966, 16)" SEVERITY error;
    ASSERT to_integer(word) = 255 REPORT "to_integer(unsigned(0 to 15))" SEVERITY error;
    ASSERT to_integer(s_min) = -128 AND to_integer(s_max) = 127
      REPORT "to_integer of the signed extremes" SEVERITY error;
    bv := "10011100";                                        -- the book's conversions
    ASSERT to_integer(unsigned(bv)) = 156 AND to_integer(signed(bv)) = -100
      REPORT "to_integer of a converted bit_vector" SEVERITY error;

    -- resize: sign extension, and a shrinking signed keeps its sign bit; an unsigned is
    -- zero-extended and keeps its low bits.
    rs8 := resize(s_m7, 8);                                  -- 11111001
    ASSERT rs8 = "11111001" REPORT "resize(-7, 8)" SEVERITY error;
    rs8 := resize(s_p7, 8);                                  -- 00000111
    ASSERT rs8 = "00000111" REPORT "resize(7, 8)" SEVERITY error;
    rs12 := resize(s_min, 12);                               -- -128 = F80
    ASSERT to_integer(rs12) = -128 REPORT "resize(-128, 12)" SEVERITY error;
    rs4 := resize(s_max, 4);                                 -- '0' & "111" = 7
    ASSERT rs4 = "0111" REPORT "resize(127, 4)" SEVERITY error;
    rs8 := "10000001";                                       -- -127
    rs4 := resize(rs8, 4);                                   -- '1' & "001" = -7
    ASSERT rs4 = "1001" REPORT "resize(-127, 4)" SEVERITY error;
    r8 := "11110000";
    r4 := resize(r8, 4);                                     -- low bits 0000
    ASSERT r4 = "0000" REPORT "resize(unsigned 240, 4)" SEVERITY error;
    r8 := resize(u4, 8);                                     -- 00001010
    ASSERT r8 = "00001010" REPORT "resize(unsigned 10, 8)" SEVERITY error;
    r16 := resize(a, 16);                                    -- 00FF, no sign extension
    ASSERT r16 = X"00FF" REPORT "resize(unsigned 255, 16)" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
