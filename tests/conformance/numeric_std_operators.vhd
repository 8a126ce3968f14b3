-- vams: stop 10 ns
--
-- numeric_std's operators as user code writes them: an explicit "=" or "<" declared with
-- `unsigned` hides the predefined one (LRM 10.3), so vectors of different lengths compare by
-- value; unary minus and abs call the package's functions; a function's result goes straight
-- into another call when its bounds are known (a `return` of a constrained object), and
-- bit_vectors compare lexicographically with the predefined operators.

LIBRARY ieee;
USE ieee.std_logic_1164.ALL;
USE ieee.numeric_std.ALL;

ENTITY tb_numeric_std_operators IS
END ENTITY tb_numeric_std_operators;

ARCHITECTURE test OF tb_numeric_std_operators IS
BEGIN
  check : PROCESS IS
    VARIABLE a : unsigned(3 DOWNTO 0) := "0101";
    VARIABLE b : unsigned(5 DOWNTO 0) := "000110";
    VARIABLE c : signed(3 DOWNTO 0) := "0011";
    VARIABLE d : signed(3 DOWNTO 0);
    VARIABLE wide : unsigned(7 DOWNTO 0);
  BEGIN
    ASSERT a = "000101" REPORT "numeric = across lengths" SEVERITY error;
    ASSERT a < b REPORT "numeric < across lengths (5 < 6)" SEVERITY error;
    ASSERT NOT (b <= a) REPORT "numeric <=" SEVERITY error;
    d := -c;
    ASSERT d = "1101" REPORT "unary minus of signed" SEVERITY error;
    ASSERT abs(d) = 3 REPORT "abs of a result compared with an integer" SEVERITY error;
    wide := resize(a, 8);
    wide := wide + b(5 DOWNTO 0);
    ASSERT to_integer(wide) = 11 REPORT "resize and + of a slice: " & integer'IMAGE(to_integer(wide))
      SEVERITY error;
    ASSERT bit_vector'("0110") < bit_vector'("1000") REPORT "predefined array ordering" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
