-- vams: stop 10 ns
--
-- The std_logic_1164 vector operators (`and`, `or`, `xor`, `not` ... on std_logic_vector), and
-- object aliases that view an array with other bounds, which those operators are written with
-- (`alias lv : std_logic_vector(1 to l'length) is l;`): reads and writes through the alias
-- reach the element at the same position.

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY tb_vector_operators IS
END ENTITY tb_vector_operators;

ARCHITECTURE test OF tb_vector_operators IS
  SIGNAL a : std_logic_vector(3 DOWNTO 0) := "1100";
  SIGNAL b : std_logic_vector(3 DOWNTO 0) := "10Z0";
  SIGNAL masked : std_logic_vector(3 DOWNTO 0);

  FUNCTION reversed ( v : bit_vector ) RETURN bit_vector IS
    VARIABLE result : bit_vector(v'LENGTH - 1 DOWNTO 0);
    ALIAS by_position : bit_vector(1 TO v'LENGTH) IS result;
    ALIAS source : bit_vector(1 TO v'LENGTH) IS v;
  BEGIN
    FOR i IN 1 TO v'LENGTH LOOP
      by_position(i) := source(v'LENGTH + 1 - i);
    END LOOP;
    RETURN result;
  END FUNCTION reversed;
BEGIN
  masked <= a AND b;

  check : PROCESS IS
  BEGIN
    WAIT FOR 1 ns;
    ASSERT masked = "1000" REPORT "and" SEVERITY failure;
    ASSERT (a OR b) = "11X0" REPORT "or" SEVERITY failure;
    ASSERT (a XOR b) = "01X0" REPORT "xor" SEVERITY failure;
    ASSERT (a NAND b) = "0111" REPORT "nand" SEVERITY failure;
    ASSERT (NOT a) = "0011" REPORT "not" SEVERITY failure;
    ASSERT reversed("1101") = "1011" REPORT "alias with other bounds" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
