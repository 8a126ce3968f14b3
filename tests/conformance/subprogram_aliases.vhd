-- vams: stop 1 ns
--
-- Aliases of subprograms and enumeration literals with signatures (LRM 4.3.3.2), as the
-- aliases chapter writes them: each alias of the overloaded `increment` denotes the overload
-- its signature names, `high` is bit's '1', and an alias of a package function is called by
-- its new name.

PACKAGE arithmetic_ops IS
  FUNCTION increment ( x : INTEGER; by : INTEGER ) RETURN INTEGER;
  FUNCTION increment ( x : REAL; by : INTEGER ) RETURN REAL;
END PACKAGE arithmetic_ops;

PACKAGE BODY arithmetic_ops IS
  FUNCTION increment ( x : INTEGER; by : INTEGER ) RETURN INTEGER IS
  BEGIN
    RETURN x + by;
  END FUNCTION increment;

  FUNCTION increment ( x : REAL; by : INTEGER ) RETURN REAL IS
  BEGIN
    RETURN x + 0.5 * REAL(by);
  END FUNCTION increment;
END PACKAGE BODY arithmetic_ops;

ENTITY tb_subprogram_aliases IS
END ENTITY tb_subprogram_aliases;

ARCHITECTURE test OF tb_subprogram_aliases IS
  ALIAS int_increment IS work.arithmetic_ops.increment [ INTEGER, INTEGER RETURN INTEGER ];
  ALIAS real_increment IS work.arithmetic_ops.increment [ REAL, INTEGER RETURN REAL ];
  ALIAS high IS std.standard.'1' [ RETURN BIT ];
  SIGNAL flag : BIT := high;
BEGIN
  check : PROCESS IS
  BEGIN
    ASSERT int_increment(2, 3) = 5 REPORT "integer overload" SEVERITY failure;
    ASSERT real_increment(2.0, 3) = 3.5 REPORT "real overload" SEVERITY failure;
    ASSERT flag = '1' AND high = '1' REPORT "literal alias" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
