-- vams: stop 30 ns
--
-- rising_edge and falling_edge of ieee.std_logic_1164 (`s'event and to_x01(s) = '1' and
-- to_x01(s'last_value) = '0'`, '0' and '1' exchanged for the falling edge) on every kind of
-- transition: 'H' and 'L' count as '1' and '0', a transition from or to 'X', 'Z', 'W' or 'U'
-- is no edge, nor is '0' to 'L'; and those of ieee.numeric_bit on a bit. Checked at each
-- event against the definition, and counted by clocked processes of the form
-- `process (clk) begin if rising_edge(clk) then ...` (which the kernel resumes at that
-- branch). Expected values from the definition; GHDL 2.0 agrees.

LIBRARY ieee;
USE ieee.std_logic_1164.ALL;
USE ieee.numeric_bit.ALL;

ENTITY tb_edge_functions IS
END ENTITY tb_edge_functions;

ARCHITECTURE test OF tb_edge_functions IS
  TYPE levels IS ARRAY (natural RANGE <>) OF std_ulogic;
  TYPE truths IS ARRAY (natural RANGE <>) OF boolean;
  -- From clk's initial '0'.
  CONSTANT seq : levels := ('1', '0', 'H', 'L', '1', 'X', '1', '0', 'X', '0', 'H', 'Z', '1',
                            'W', '0', 'L', 'H', 'U', '1', 'L');
  CONSTANT rises_at : truths := (true, false, true, false, true, false, false, false, false,
                                 false, true, false, false, false, false, false, true, false,
                                 false, false);
  CONSTANT falls_at : truths := (false, true, false, true, false, false, false, true, false,
                                 false, false, false, false, false, false, false, false, false,
                                 false, true);
  SIGNAL clk : std_ulogic := '0';
  SIGNAL b : bit := '0';
  SIGNAL rises, falls, b_rises, b_falls : natural := 0;
BEGIN
  drive : PROCESS IS
  BEGIN
    FOR i IN seq'range LOOP
      clk <= seq(i);
      WAIT FOR 1 ns;
    END LOOP;
    b <= '1';
    WAIT FOR 1 ns;
    b <= '0';
    WAIT FOR 1 ns;
    b <= '1';
    WAIT;
  END PROCESS drive;

  check : PROCESS IS
  BEGIN
    FOR i IN seq'range LOOP
      WAIT ON clk;
      ASSERT rising_edge(clk) = rises_at(i)
        REPORT "rising_edge at transition " & integer'image(i) SEVERITY failure;
      ASSERT falling_edge(clk) = falls_at(i)
        REPORT "falling_edge at transition " & integer'image(i) SEVERITY failure;
    END LOOP;
    WAIT;
  END PROCESS check;

  count_rises : PROCESS (clk) IS
  BEGIN
    IF rising_edge(clk) THEN
      rises <= rises + 1;
    END IF;
  END PROCESS count_rises;

  count_falls : PROCESS (clk) IS
  BEGIN
    IF falling_edge(clk) THEN
      falls <= falls + 1;
    END IF;
  END PROCESS count_falls;

  count_b_rises : PROCESS (b) IS
  BEGIN
    IF rising_edge(b) THEN
      b_rises <= b_rises + 1;
    END IF;
  END PROCESS count_b_rises;

  count_b_falls : PROCESS (b) IS
  BEGIN
    IF falling_edge(b) THEN
      b_falls <= b_falls + 1;
    END IF;
  END PROCESS count_b_falls;

  final : PROCESS IS
  BEGIN
    WAIT FOR 25 ns;
    ASSERT rises = 5 REPORT "rises: " & integer'image(rises) SEVERITY failure;
    ASSERT falls = 4 REPORT "falls: " & integer'image(falls) SEVERITY failure;
    ASSERT b_rises = 2 REPORT "b rises: " & integer'image(b_rises) SEVERITY failure;
    ASSERT b_falls = 1 REPORT "b falls: " & integer'image(b_falls) SEVERITY failure;
    REPORT "edges checked" SEVERITY note;
    WAIT;
  END PROCESS final;
END ARCHITECTURE test;
