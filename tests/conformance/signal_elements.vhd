-- vams: stop 100 ns
--
-- Signal array elements as assignment targets (LRM 8.4, 12.6.1): each scalar element has
-- its own driver, so a generate's processes may each drive one element of an unresolved
-- bit_vector, a loop may assign elements by a computed index, pending transactions on one
-- element survive assignments to another, and two drivers of one std_logic element are
-- resolved element by element. An alias with other bounds writes the element at the same
-- position.

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY tb_signal_elements IS
END ENTITY tb_signal_elements;

ARCHITECTURE test OF tb_signal_elements IS
  SIGNAL dout : bit_vector(7 DOWNTO 0);
  SIGNAL ready : bit_vector(0 TO 3);
  SIGNAL data_bus : std_logic_vector(1 DOWNTO 0) := "ZZ";
  SIGNAL counts : integer_vector(0 TO 2) := (OTHERS => 0);
  SIGNAL flags : bit_vector(3 DOWNTO 0);
  ALIAS flag_list : bit_vector(1 TO 4) IS flags;
BEGIN
  stages : FOR k IN 0 TO 3 GENERATE
    ready(k) <= '1' AFTER (k + 1) * 1 ns;
  END GENERATE stages;

  driver_a : PROCESS IS
  BEGIN
    data_bus(0) <= '1';
    WAIT;
  END PROCESS driver_a;

  driver_b : PROCESS IS
  BEGIN
    data_bus(0) <= '0';
    data_bus(1) <= 'H';
    WAIT;
  END PROCESS driver_b;

  shifter : PROCESS IS
  BEGIN
    dout <= (OTHERS => '0');
    WAIT FOR 5 ns;
    FOR i IN 0 TO 7 LOOP
      IF i MOD 2 = 0 THEN
        dout(i) <= '1';
      END IF;
    END LOOP;
    counts(1) <= 5;
    flag_list(1) <= '1';
    WAIT FOR 5 ns;
    ASSERT dout = "01010101" REPORT "element assignments" SEVERITY failure;
    ASSERT ready = "1111" REPORT "generated element drivers" SEVERITY failure;
    ASSERT data_bus(0) = 'X' AND data_bus(1) = 'H' REPORT "resolution" SEVERITY failure;
    ASSERT counts(1) = 5 AND counts(0) = 0 REPORT "integer element" SEVERITY failure;
    ASSERT flags = "1000" REPORT "element written through an alias" SEVERITY failure;
    dout(3) <= '1' AFTER 10 ns;
    dout(5) <= '1' AFTER 20 ns;
    WAIT FOR 15 ns;
    ASSERT dout = "01011101" REPORT "pending transaction of another element" SEVERITY failure;
    WAIT FOR 10 ns;
    ASSERT dout = "01111101" REPORT "second element transaction" SEVERITY failure;
    WAIT;
  END PROCESS shifter;
END ARCHITECTURE test;
