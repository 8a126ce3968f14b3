-- vams: stop 1 ms
--
-- 'pos, 'val, 'succ, 'pred, 'leftof and 'rightof on enumeration, boolean, integer and time
-- types, folded where static and computed at run time from variables, including the
-- textbook time-to-real idiom `real(time'pos(now)) * 1.0e-15`; 'value reads a literal back
-- from a string (any case, blanks around it ignored), the inverse of 'image.

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

  read_back : PROCESS
    TYPE logic_level IS (unknown, low, undriven, high);
    SUBTYPE set_index_range IS integer RANGE 21 DOWNTO 11;
    VARIABLE text : string(1 TO 5) := " High";
  BEGIN
    ASSERT logic_level'value("Low") = low REPORT "'value of a literal" SEVERITY ERROR;
    ASSERT logic_level'value(text) = high REPORT "'value of a variable" SEVERITY ERROR;
    ASSERT set_index_range'value("20") = 20 REPORT "integer'value" SEVERITY ERROR;
    ASSERT real'value(" 2.5e3 ") = 2500.0 REPORT "real'value" SEVERITY ERROR;
    ASSERT time'value("10 ns") = 10 ns REPORT "time'value" SEVERITY ERROR;
    ASSERT boolean'value("TRUE") REPORT "boolean'value" SEVERITY ERROR;
    ASSERT character'value("'x'") = 'x' REPORT "character'value" SEVERITY ERROR;
    ASSERT state'value(state'image(stopped)) = stopped REPORT "'image and 'value" SEVERITY ERROR;
    WAIT;
  END PROCESS read_back;
END ARCHITECTURE test;
