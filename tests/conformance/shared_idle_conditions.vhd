-- vams: stop 100 ns
--
-- Clocked processes of the form `process (clk) begin if cond then ... end if;`, which the
-- kernel resumes at that branch, evaluating a condition of signals alone once per cycle for
-- all the processes that test the same one: processes testing `clk = '1'` interleaved with
-- others testing `clk = '0'` (another condition on the same signal), `en = '1'` (the same
-- test of another signal) and a variable of their own (evaluated per process), each
-- counting its activations. At time 0 every process runs once. Expected values by counting
-- the clock's events (a rising edge at 5, 15, ..., 95 ns, a falling one at 10, ..., 90 ns;
-- `en` is '1' from 32 to 62 ns); GHDL 2.0 agrees.

ENTITY tb_shared_idle_conditions IS
END ENTITY tb_shared_idle_conditions;

ARCHITECTURE test OF tb_shared_idle_conditions IS
  SIGNAL clk, en : bit := '0';
  SIGNAL high1, low1, high2, once, high3, enabled, low2 : natural := 0;
BEGIN
  clock : PROCESS IS
  BEGIN
    WAIT FOR 5 ns;
    clk <= NOT clk;
  END PROCESS clock;

  en <= '1' AFTER 32 ns, '0' AFTER 62 ns;

  count_high1 : PROCESS (clk) IS
  BEGIN
    IF clk = '1' THEN
      high1 <= high1 + 1;
    END IF;
  END PROCESS count_high1;

  count_low1 : PROCESS (clk) IS
  BEGIN
    IF clk = '0' THEN
      low1 <= low1 + 1;
    END IF;
  END PROCESS count_low1;

  count_high2 : PROCESS (clk) IS
  BEGIN
    IF clk = '1' THEN
      high2 <= high2 + 1;
    END IF;
  END PROCESS count_high2;

  count_once : PROCESS (clk) IS
    VARIABLE armed : boolean := true;
  BEGIN
    IF armed THEN
      armed := false;
      once <= once + 1;
    END IF;
  END PROCESS count_once;

  count_high3 : PROCESS (clk) IS
  BEGIN
    IF clk = '1' THEN
      high3 <= high3 + 1;
    END IF;
  END PROCESS count_high3;

  count_enabled : PROCESS (clk) IS
  BEGIN
    IF en = '1' THEN
      enabled <= enabled + 1;
    END IF;
  END PROCESS count_enabled;

  count_low2 : PROCESS (clk) IS
  BEGIN
    IF clk = '0' THEN
      low2 <= low2 + 1;
    END IF;
  END PROCESS count_low2;

  check : PROCESS IS
  BEGIN
    WAIT FOR 99 ns;
    ASSERT high1 = 10 REPORT "high1 = " & integer'image(high1) SEVERITY failure;
    ASSERT high2 = 10 REPORT "high2 = " & integer'image(high2) SEVERITY failure;
    ASSERT high3 = 10 REPORT "high3 = " & integer'image(high3) SEVERITY failure;
    ASSERT low1 = 10 REPORT "low1 = " & integer'image(low1) SEVERITY failure;
    ASSERT low2 = 10 REPORT "low2 = " & integer'image(low2) SEVERITY failure;
    ASSERT once = 1 REPORT "once = " & integer'image(once) SEVERITY failure;
    ASSERT enabled = 6 REPORT "enabled = " & integer'image(enabled) SEVERITY failure;
    REPORT "counts checked";
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
