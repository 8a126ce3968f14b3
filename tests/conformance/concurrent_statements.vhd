-- vams: stop 1 ms
--
-- Statement forms of textbook testbenches: a concurrent procedure call, a postponed process,
-- an object alias, and `wait on ... until ... for ...`.

ENTITY tb_concurrent_statements IS
END ENTITY tb_concurrent_statements;

ARCHITECTURE test OF tb_concurrent_statements IS
  SIGNAL a, b : BIT := '0';
  SIGNAL seen : INTEGER := 0;
  PROCEDURE invert (SIGNAL s : OUT BIT; v : BIT) IS
  BEGIN
    s <= NOT v;
  END PROCEDURE invert;
  ALIAS a_alias : BIT IS a;
BEGIN
  invert(b, a);                          -- concurrent procedure call: b follows not a

  watch : POSTPONED PROCESS (b)
  BEGIN
    seen <= seen + 1;
  END PROCESS watch;

  stimulus : PROCESS
  BEGIN
    WAIT FOR 10 us;
    a <= '1';
    WAIT;
  END PROCESS stimulus;

  check : PROCESS
  BEGIN
    WAIT ON a UNTIL b = '1' FOR 5 us;    -- b is '1' after the first delta
    ASSERT b = '1' REPORT "b follows not a" SEVERITY ERROR;
    WAIT ON b UNTIL b = '0' FOR 50 us;   -- a rises at 10 us
    ASSERT NOW = 10 us AND b = '0' AND a_alias = '1'
      REPORT "b falls when a rises" SEVERITY ERROR;
    ASSERT seen >= 1 REPORT "the postponed process ran" SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
