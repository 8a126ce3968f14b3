-- vams: stop 200 ns
--
-- Elements and slices of signals where a whole signal is named (LRM 1.1.1.2, 4.3.2.2):
-- port actuals `in1 => parity(1)` and `d => bus(7 DOWNTO 4)`, a signal parameter
-- `rising_edge(clocks(0))`, `WAIT ON v(2)`, and attributes of an element (`v(1)'EVENT`,
-- `v(2)'LAST_EVENT`). Each element has its own events: a process waiting on one element
-- does not wake when another changes. An OUT or INOUT port's default is the initial value
-- of the drivers behind it (LRM 12.6.1), so a self-restarting clock whose port defaults to
-- '0' runs although its actual starts at 'U' (the book's mixed-signal case study). A
-- process variable may start from a signal's value (LRM 12.3.1.4). Written the way the
-- case studies write it.

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY and_gate IS
  PORT (in1, in2 : IN std_logic;  output : OUT std_logic);
END ENTITY and_gate;

ARCHITECTURE ideal OF and_gate IS
BEGIN
  output <= in1 AND in2 AFTER 1 ns;
END ARCHITECTURE ideal;

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY edge_counter IS
  PORT (clk : IN std_logic;  count : OUT integer := 0);
END ENTITY edge_counter;

ARCHITECTURE behav OF edge_counter IS
BEGIN
  PROCESS (clk) IS
    VARIABLE n : integer := 0;
  BEGIN
    IF rising_edge(clk) THEN
      n := n + 1;
      count <= n;
    END IF;
  END PROCESS;
END ARCHITECTURE behav;

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY inverter_4 IS
  PORT (d : IN std_logic_vector(3 DOWNTO 0);  q : OUT std_logic_vector(3 DOWNTO 0));
END ENTITY inverter_4;

ARCHITECTURE behav OF inverter_4 IS
BEGIN
  q <= NOT d;
END ARCHITECTURE behav;

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY clock_en IS
  GENERIC (pw : time);
  PORT (enable : IN std_logic;  clock_out : INOUT std_logic := '0');
END ENTITY clock_en;

ARCHITECTURE ideal OF clock_en IS
BEGIN
  PROCESS (clock_out, enable) IS
  BEGIN
    IF clock_out = '0' AND enable = '1' THEN
      clock_out <= '1' AFTER pw, '0' AFTER 2 * pw;
    END IF;
  END PROCESS;
END ARCHITECTURE ideal;

LIBRARY ieee;  USE ieee.std_logic_1164.ALL;

ENTITY tb_element_port_actuals IS
END ENTITY tb_element_port_actuals;

ARCHITECTURE test OF tb_element_port_actuals IS
  SIGNAL v : std_logic_vector(1 TO 4) := "0000";
  SIGNAL w : std_logic_vector(7 DOWNTO 0) := (OTHERS => '0');
  SIGNAL clocks : std_logic_vector(0 TO 1) := "00";
  SIGNAL n_v1, n_clock : integer;
  SIGNAL wakes : integer := 0;
  SIGNAL run_clk : std_logic;              -- 'U' until the clock's driver says otherwise
  SIGNAL enable : std_logic := '1';
  SIGNAL clock_edges : integer := 0;
BEGIN
  gate : ENTITY work.and_gate(ideal)
    PORT MAP (in1 => v(1), in2 => v(2), output => v(3));
  count_v1 : ENTITY work.edge_counter(behav)
    PORT MAP (clk => v(1), count => n_v1);
  count_clock : ENTITY work.edge_counter(behav)
    PORT MAP (clk => clocks(0), count => n_clock);
  nibble : ENTITY work.inverter_4(behav)
    PORT MAP (d => w(7 DOWNTO 4), q => w(3 DOWNTO 0));
  clk_gen : ENTITY work.clock_en(ideal)
    GENERIC MAP (pw => 5 ns)
    PORT MAP (enable => enable, clock_out => run_clk);

  watch : PROCESS IS
  BEGIN
    WAIT ON v(2);
    wakes <= wakes + 1;
  END PROCESS watch;

  edges : PROCESS (run_clk) IS
  BEGIN
    IF rising_edge(run_clk) THEN
      clock_edges <= clock_edges + 1;
    END IF;
  END PROCESS edges;

  stimulus : PROCESS IS
    VARIABLE start_edges : integer := clock_edges;   -- a snapshot, not a static value
  BEGIN
    ASSERT start_edges = 0 REPORT "variable initialised from a signal" SEVERITY error;
    v(1) <= '1';
    WAIT FOR 5 ns;
    ASSERT v(3) = '0' REPORT "1 and 0" SEVERITY error;
    v(2) <= '1';
    WAIT FOR 5 ns;
    ASSERT v(3) = '1' REPORT "1 and 1" SEVERITY error;
    v(4) <= '1';                             -- an event on v, none on v(1) or v(2)
    WAIT FOR 5 ns;
    v(1) <= '0';
    WAIT FOR 5 ns;
    v(1) <= '1';
    clocks(1) <= '1';                        -- not the counted element
    WAIT FOR 1 ns;
    ASSERT v(1)'LAST_EVENT = 1 ns REPORT "v(1)'last_event" SEVERITY error;
    ASSERT v(2)'LAST_EVENT = 16 ns REPORT "v(2)'last_event" SEVERITY error;
    ASSERT NOT v(1)'EVENT REPORT "v(1)'event a delta later" SEVERITY error;
    ASSERT n_v1 = 2 REPORT "two rising edges of v(1), got " & integer'IMAGE(n_v1)
      SEVERITY error;
    ASSERT n_clock = 0 REPORT "no edge of clocks(0), got " & integer'IMAGE(n_clock)
      SEVERITY error;
    ASSERT wakes = 1 REPORT "one event on v(2), woken " & integer'IMAGE(wakes) & " times"
      SEVERITY error;
    clocks(0) <= '1';
    w(7 DOWNTO 4) <= "1010";
    WAIT FOR 1 ns;
    ASSERT n_clock = 1 REPORT "an edge of clocks(0)" SEVERITY error;
    ASSERT w = "10100101" REPORT "the slice port inverts the upper nibble" SEVERITY error;
    WAIT FOR 98 ns;
    -- Edges at 5, 15, ..., 115 ns: 12 of them.
    ASSERT clock_edges = 12
      REPORT "the clock runs from its port's default: " & integer'IMAGE(clock_edges) & " edges"
      SEVERITY error;
    WAIT;
  END PROCESS stimulus;
END ARCHITECTURE test;
