-- vams: stop 10 ns
--
-- Slices (LRM 6.5) of variables, signals and strings, read and assigned, with static and
-- run-time bounds, in both directions, as Ashenden's examples use them: a byte swap, a
-- field of an instruction word, a name in a fixed-width string. A slice runs in its array's
-- direction; its length must match the value assigned to it.

ENTITY tb_slices IS
END ENTITY tb_slices;

ARCHITECTURE test OF tb_slices IS
  SIGNAL word : bit_vector(15 DOWNTO 0) := X"12AB";
  SIGNAL swapped : bit_vector(15 DOWNTO 0);
  SIGNAL flags : bit_vector(0 TO 7) := (OTHERS => '0');
BEGIN
  swapped <= word(7 DOWNTO 0) & word(15 DOWNTO 8);

  check : PROCESS IS
    VARIABLE instr : bit_vector(1 TO 16) := "1011001111000101";
    VARIABLE acc : bit_vector(7 DOWNTO 0) := "10110011";
    VARIABLE name : string(1 TO 8) := "resistor";
    VARIABLE n : integer := 3;
  BEGIN
    ASSERT instr(1 TO 4) = "1011" REPORT "opcode field" SEVERITY error;
    ASSERT acc(7 DOWNTO 4) = "1011" REPORT "upper nibble" SEVERITY error;
    ASSERT acc(n DOWNTO 0) = "0011" REPORT "a slice with a run-time bound" SEVERITY error;
    ASSERT name(1 TO 3) = "res" REPORT "a string slice" SEVERITY error;
    instr(1 TO 4) := "0000";
    ASSERT instr = "0000001111000101" REPORT "a slice target" SEVERITY error;
    acc(n DOWNTO n - 1) := "11";
    ASSERT acc = "10111111" REPORT "a slice target with run-time bounds" SEVERITY error;
    name(1 TO 3) := "cap";
    ASSERT name = "capistor" REPORT "a string slice target" SEVERITY error;
    flags(2 TO 4) <= "111";
    WAIT FOR 1 ns;
    ASSERT swapped = X"AB12" REPORT "byte swap by slices" SEVERITY error;
    ASSERT flags = "00111000" REPORT "a signal slice target" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
