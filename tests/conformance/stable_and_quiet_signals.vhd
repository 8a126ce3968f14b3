-- vams: stop 200 ns
--
-- `S'stable(T)` and `S'quiet(T)` are implicit signals (LRM 14.1): a process may wait on
-- them, and a concurrent statement that reads them re-runs when they change. `s'stable(T)`
-- falls in the cycle of an event on `s` and rises T after the last one; `s'quiet(T)` does
-- the same for transactions, with or without a change of value.

ENTITY tb_stable_and_quiet_signals IS
END ENTITY tb_stable_and_quiet_signals;

ARCHITECTURE test OF tb_stable_and_quiet_signals IS
  SIGNAL s : integer := 0;
  SIGNAL settled : boolean;
  SIGNAL settled_at, quiet_at, edge_at : time := 0 ns;
  SIGNAL edges : natural := 0;
  SIGNAL clk, d, q : bit := '0';
  TYPE int_arr IS ARRAY (1 TO 3) OF integer;
  SIGNAL arr : int_arr := (0, 0, 0);
BEGIN
  -- Events at 10, 14 and 17 ns; a transaction without event at 60 ns.
  stimulus : PROCESS IS
  BEGIN
    WAIT FOR 10 ns;
    s <= 1;
    WAIT FOR 4 ns;
    s <= 2;
    WAIT FOR 3 ns;
    s <= 3;
    WAIT FOR 43 ns;
    s <= 3;
    WAIT;
  END PROCESS stimulus;

  -- A concurrent statement reading the implicit signal follows it.
  settled <= s'stable(20 ns);

  waiter : PROCESS IS
  BEGIN
    WAIT UNTIL s'stable(20 ns);
    settled_at <= now;
    WAIT UNTIL s'quiet(5 ns);
    quiet_at <= now;
    WAIT;
  END PROCESS waiter;

  -- `not s'stable` is true in the very cycle of an event.
  edge_counter : PROCESS IS
  BEGIN
    WAIT UNTIL NOT s'stable;
    ASSERT s'event REPORT "s'stable fell outside the cycle of an event" SEVERITY error;
    edges <= edges + 1;
    edge_at <= now;
  END PROCESS edge_counter;

  -- A composite signal: an event on one element is an event on the signal, so its
  -- `'stable` is false in that cycle (GHDL 2.0 leaves it true at the second change).
  arr <= (1, 2, 3) AFTER 5 ns, (1, 2, 4) AFTER 7 ns;
  composite : PROCESS (arr) IS
  BEGIN
    ASSERT arr'stable = NOT arr'event
      REPORT "arr'stable is " & boolean'image(arr'stable) & " with arr'event "
        & boolean'image(arr'event)
      SEVERITY error;
  END PROCESS composite;

  -- The old idiom for a clock edge: `not clk'stable` in a concurrent statement.
  q <= d WHEN NOT clk'stable AND clk = '1';
  clk <= NOT clk AFTER 10 ns WHEN now < 100 ns;
  d <= '1' AFTER 25 ns, '0' AFTER 65 ns;

  check : PROCESS IS
  BEGIN
    WAIT FOR 12 ns;
    ASSERT NOT settled REPORT "s'stable(20 ns) is false 2 ns after an event" SEVERITY error;
    WAIT FOR 100 ns;
    ASSERT settled REPORT "s'stable(20 ns) is true again" SEVERITY error;
    ASSERT settled_at = 37 ns
      REPORT "wait until s'stable(20 ns) resumed at " & time'image(settled_at) & ", not 37 ns"
      SEVERITY error;
    ASSERT quiet_at = 65 ns
      REPORT "wait until s'quiet(5 ns) resumed at " & time'image(quiet_at) & ", not 65 ns"
      SEVERITY error;
    ASSERT edges = 3 REPORT "three events, " & integer'image(edges) & " edges" SEVERITY error;
    ASSERT edge_at = 17 ns REPORT "the last edge at 17 ns" SEVERITY error;
    -- Rising edges at 10, 30, 50, 70, 90 ns: d is 1 from 25 to 65 ns.
    ASSERT q = '0' REPORT "q follows d at the rising edge of 90 ns" SEVERITY error;
    WAIT;
  END PROCESS check;

  clocked : PROCESS (q) IS
  BEGIN
    IF q = '1' THEN
      ASSERT now = 30 ns REPORT "q rose at " & time'image(now) & ", not 30 ns" SEVERITY error;
    ELSIF now > 0 ns THEN
      ASSERT now = 70 ns REPORT "q fell at " & time'image(now) & ", not 70 ns" SEVERITY error;
    END IF;
  END PROCESS clocked;
END ARCHITECTURE test;
