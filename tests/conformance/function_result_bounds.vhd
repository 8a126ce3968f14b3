-- vams: stop 10 ns
--
-- A function result whose length comes from a scalar argument (to_signed(x, 8),
-- to_unsigned(n, a'length), resize(s, 12)) passed straight into another call, as the books
-- write it: Ashenden's increment procedure (a := bit_vector(signed(a) + to_signed(n,
-- a'length)), here of std_logic_vector), a sum of two conversions compared through
-- to_integer, a resize of a conversion, and a function of the model's own that builds its
-- result by recursion with "&". Lengths that match are assigned as they are (LRM 8.5).

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;  USE ieee.numeric_std.ALL;

ENTITY tb_function_result_bounds IS
  GENERIC ( width : positive := 6 );
END ENTITY tb_function_result_bounds;

ARCHITECTURE test OF tb_function_result_bounds IS
  -- n copies of b, built as vbuild builds numeric_std's results.
  FUNCTION ones ( b : bit; n : natural ) RETURN bit_vector IS
    CONSTANT none : bit_vector(1 TO 0) := (OTHERS => '0');
  BEGIN
    IF n = 0 THEN
      RETURN none;
    END IF;
    RETURN b & ones(b, n - 1);
  END FUNCTION ones;

  FUNCTION count ( v : bit_vector ) RETURN natural IS
    VARIABLE k : natural := 0;
  BEGIN
    FOR i IN v'RANGE LOOP
      IF v(i) = '1' THEN
        k := k + 1;
      END IF;
    END LOOP;
    RETURN k;
  END FUNCTION count;
BEGIN
  check : PROCESS IS
    PROCEDURE increment ( a : INOUT std_logic_vector; n : IN integer := 1 ) IS
    BEGIN
      a := std_logic_vector(signed(a) + to_signed(n, a'length));
    END PROCEDURE increment;

    VARIABLE x : signed(11 DOWNTO 0);
    VARIABLE u : unsigned(7 DOWNTO 0) := "00001111";
    VARIABLE s : signed(3 DOWNTO 0) := "1010";               -- -6
    VARIABLE count_slv : std_logic_vector(15 DOWNTO 0) := X"0002";
    VARIABLE m : integer := -3;
    VARIABLE slv : std_logic_vector(7 DOWNTO 0);
  BEGIN
    WAIT FOR 1 ns;
    x := resize(to_signed(5, 8), 12);
    ASSERT to_integer(x) = 5 REPORT "resize(to_signed(5, 8), 12)" SEVERITY error;
    x := resize(to_signed(m, 8), 12);
    ASSERT to_integer(x) = -3 REPORT "resize(to_signed(m, 8), 12)" SEVERITY error;
    ASSERT to_integer(to_signed(-3, 4) + to_signed(1, 4)) = -2
      REPORT "to_signed(-3, 4) + to_signed(1, 4)" SEVERITY error;
    ASSERT to_integer(to_signed(m, 8) * to_signed(m, 8)) = 9
      REPORT "a product of two conversions" SEVERITY error;
    ASSERT to_integer(resize(s, 12)) = -6 REPORT "to_integer(resize(s, 12))" SEVERITY error;
    ASSERT to_integer(u + to_unsigned(1, u'length)) = 16
      REPORT "u + to_unsigned(1, u'length)" SEVERITY error;
    ASSERT to_integer(resize(u, width)) = 15 REPORT "a length from a generic" SEVERITY error;
    slv := std_logic_vector(resize(to_unsigned(200, 9), 8));
    ASSERT slv = "11001000" REPORT "std_logic_vector(resize(to_unsigned(200, 9), 8))"
      SEVERITY error;
    increment(count_slv, 2);
    increment(count_slv);
    ASSERT count_slv = X"0005" REPORT "increment(count_slv, 2); increment(count_slv)"
      SEVERITY error;
    ASSERT count(ones('1', 5)) = 5 REPORT "a result built by recursion with &" SEVERITY error;
    ASSERT count(ones('1', 3) & ones('0', 2)) = 3 REPORT "two of them joined" SEVERITY error;
    REPORT "function results checked";
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
