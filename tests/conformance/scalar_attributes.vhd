-- vams: stop 1 ms
--
-- 'pos, 'val, 'succ, 'pred, 'leftof and 'rightof on enumeration, boolean, integer and time
-- types, folded where static and computed at run time from variables, including the
-- textbook time-to-real idiom `real(time'pos(now)) * 1.0e-15`.

ENTITY tb_scalar_attributes IS
END ENTITY tb_scalar_attributes;

ARCHITECTURE test OF tb_scalar_attributes IS
  TYPE state IS (idle, running, stopped);
  CONSTANT first_pos : INTEGER := state'pos(running);   -- folded: 1
BEGIN
  check : PROCESS
    VARIABLE s : state := idle;
    VARIABLE k : INTEGER := 2;
    VARIABLE seconds : REAL;
  BEGIN
    ASSERT first_pos = 1 REPORT "state'pos(running)" SEVERITY ERROR;
    ASSERT state'val(k) = stopped REPORT "state'val(2)" SEVERITY ERROR;
    ASSERT state'succ(s) = running REPORT "state'succ(idle)" SEVERITY ERROR;
    ASSERT state'pred(stopped) = running REPORT "state'pred" SEVERITY ERROR;
    ASSERT state'rightof(s) = running REPORT "state'rightof" SEVERITY ERROR;
    ASSERT state'leftof(running) = idle REPORT "state'leftof" SEVERITY ERROR;
    ASSERT boolean'pos(true) = 1 AND boolean'val(0) = false REPORT "boolean" SEVERITY ERROR;
    ASSERT integer'succ(k) = 3 AND integer'pred(k) = 1 AND integer'pos(k) = 2
      REPORT "integer" SEVERITY ERROR;
    ASSERT time'pos(1 ns) = 1000000 REPORT "time'pos(1 ns)" SEVERITY ERROR;
    ASSERT time'val(1000) = 1 ps REPORT "time'val" SEVERITY ERROR;
    WAIT FOR 250 us;
    seconds := real(time'pos(now)) * 1.0e-15;
    ASSERT ABS(seconds - 250.0e-6) < 1.0e-12 REPORT "time to real" SEVERITY ERROR;
    s := state'succ(state'succ(s));
    ASSERT s = stopped REPORT "succ twice" SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
