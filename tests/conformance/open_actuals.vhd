-- vams: stop 2 ns
--
-- `open` as the actual of a subprogram parameter that has a default (LRM 2.1.1.1): the
-- default applies, in a concurrent procedure call (the guards-and-blocks chapter's
-- `alu : perform_alu_op(alu_opcode, source1, source2, destination, open);`), a sequential
-- one and a function call, by position and by name.

ENTITY tb_open_actuals IS
END ENTITY tb_open_actuals;

ARCHITECTURE test OF tb_open_actuals IS
  PROCEDURE scale (SIGNAL a : IN INTEGER; SIGNAL b : OUT INTEGER;
                   CONSTANT k : IN INTEGER := 3) IS
  BEGIN
    b <= a * k;
  END PROCEDURE scale;

  FUNCTION offset (x : INTEGER; d : INTEGER := 10) RETURN INTEGER IS
  BEGIN
    RETURN x + d;
  END FUNCTION offset;

  SIGNAL x, y, z : INTEGER := 0;
BEGIN
  c1 : scale (x, y, OPEN);

  PROCESS
  BEGIN
    x <= 2;
    WAIT FOR 1 ns;
    ASSERT y = 6 REPORT "concurrent call: y = " & INTEGER'IMAGE(y) SEVERITY ERROR;
    scale(a => x, b => z, k => OPEN);
    WAIT FOR 1 ns;
    ASSERT z = 6 REPORT "sequential call: z = " & INTEGER'IMAGE(z) SEVERITY ERROR;
    ASSERT offset(1, OPEN) = 11 REPORT "offset(1, open)" SEVERITY ERROR;
    ASSERT offset(x => 1, d => OPEN) = 11 REPORT "offset by name" SEVERITY ERROR;
    WAIT;
  END PROCESS;
END ARCHITECTURE test;
