-- vams: stop 4 ms
--
-- A simultaneous case statement selecting a source's equation by a signal of an
-- enumeration type, and a straight-line function called from an equation: the source
-- gives 0 V, then 2 V, then a soft-limited 3 V (x / (1 + |x| / 4) = 12/7 V).

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_simultaneous_case IS
END ENTITY tb_simultaneous_case;

ARCHITECTURE test OF tb_simultaneous_case IS
  TYPE mode_type IS (off, fixed, limited);
  SIGNAL mode : mode_type := off;
  TERMINAL n : ELECTRICAL;
  QUANTITY v ACROSS i THROUGH n TO ELECTRICAL_REF;

  FUNCTION soft_limit (x, knee : REAL) RETURN REAL IS
  BEGIN
    RETURN x / (1.0 + ABS(x) / knee);
  END FUNCTION soft_limit;
BEGIN
  CASE mode USE
    WHEN off => v == 0.0;
    WHEN fixed => v == 2.0;
    WHEN limited => v == soft_limit(3.0, 4.0);
  END CASE;
  BREAK ON mode;

  drive : PROCESS
  BEGIN
    WAIT FOR 1 ms;
    mode <= fixed;
    WAIT FOR 1 ms;
    mode <= limited;
    WAIT;
  END PROCESS drive;

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(v) < 1.0e-9 REPORT "off: " & REAL'IMAGE(v) SEVERITY ERROR;
    WAIT FOR 1 ms;
    ASSERT ABS(v - 2.0) < 1.0e-9 REPORT "fixed: " & REAL'IMAGE(v) SEVERITY ERROR;
    WAIT FOR 1 ms;
    ASSERT ABS(v - 12.0 / 7.0) < 1.0e-9 REPORT "limited: " & REAL'IMAGE(v) SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
