-- vams: stop 100 ns
--
-- Shared variables of ordinary types (VHDL-93, as Ashenden's `operation_count` and many
-- testbenches still write them; VHDL-2002 reserves shared variables to protected types, and
-- vams accepts both): one object that every process reads and writes, here a counter two
-- processes increment and an array a third one fills, read back by a checker.

ENTITY tb_shared_variables IS
END ENTITY tb_shared_variables;

ARCHITECTURE instrumented OF tb_shared_variables IS
  SHARED VARIABLE operation_count : natural := 0;
  TYPE sample_array IS ARRAY (1 TO 4) OF integer;
  SHARED VARIABLE samples : sample_array := (OTHERS => 0);
  SIGNAL clk : bit := '0';
BEGIN
  clk <= NOT clk AFTER 5 ns WHEN now < 40 ns ELSE clk;

  producer_a : PROCESS (clk) IS
  BEGIN
    IF clk = '1' THEN
      operation_count := operation_count + 1;
    END IF;
  END PROCESS producer_a;

  producer_b : PROCESS (clk) IS
  BEGIN
    IF clk = '0' AND clk'EVENT THEN
      operation_count := operation_count + 10;
    END IF;
  END PROCESS producer_b;

  filler : PROCESS IS
  BEGIN
    FOR k IN samples'RANGE LOOP
      WAIT FOR 10 ns;
      samples(k) := k * k;
    END LOOP;
    WAIT;
  END PROCESS filler;

  check : PROCESS IS
  BEGIN
    WAIT FOR 60 ns;
    -- Four rising edges (5, 15, 25, 35 ns) and four falling ones (10, 20, 30, 40 ns).
    ASSERT operation_count = 44
      REPORT "operation_count = " & integer'IMAGE(operation_count) SEVERITY failure;
    ASSERT samples = (1, 4, 9, 16) REPORT "samples" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE instrumented;
