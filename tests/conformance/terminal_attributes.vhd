-- vams: stop 1 ms
--
-- The terminal attributes of LRM 1076.1 14.1: `T'reference` is the across quantity from T
-- to its nature's reference terminal (a node voltage), `T'contribution` the sum of the
-- through quantities at T (leaving T positive) in the region that reads it and below. A
-- 1 V source feeds two 2-ohm resistors in series: the middle node is at 0.5 V, each
-- resistor's own contribution at its plus terminal is its current, 0.25 A, and at the top
-- the contributions at the source node sum to zero (Kirchhoff's current law).

LIBRARY IEEE_PROPOSED;
USE IEEE_PROPOSED.ELECTRICAL_SYSTEMS.ALL;

ENTITY two_ohms IS
  PORT (TERMINAL p, n : ELECTRICAL);
END ENTITY two_ohms;

ARCHITECTURE ideal OF two_ohms IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == 2.0 * i;

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(p'CONTRIBUTION - 0.25) < 1.0e-9
      REPORT "p'contribution = " & REAL'IMAGE(p'CONTRIBUTION) SEVERITY ERROR;
    ASSERT ABS(n'CONTRIBUTION + 0.25) < 1.0e-9
      REPORT "n'contribution = " & REAL'IMAGE(n'CONTRIBUTION) SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE ideal;

LIBRARY IEEE_PROPOSED;
USE IEEE_PROPOSED.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_terminal_attributes IS
END ENTITY tb_terminal_attributes;

ARCHITECTURE test OF tb_terminal_attributes IS
  TERMINAL a, b : ELECTRICAL;
  QUANTITY vs ACROSS i_src THROUGH a;
BEGIN
  vs == 1.0;
  r1 : ENTITY work.two_ohms(ideal) PORT MAP (p => a, n => b);
  r2 : ENTITY work.two_ohms(ideal) PORT MAP (p => b, n => ELECTRICAL_REF);

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(b'REFERENCE - 0.5) < 1.0e-9
      REPORT "b'reference = " & REAL'IMAGE(b'REFERENCE) SEVERITY ERROR;
    ASSERT ABS(a'REFERENCE - 1.0) < 1.0e-9
      REPORT "a'reference = " & REAL'IMAGE(a'REFERENCE) SEVERITY ERROR;
    ASSERT ABS(a'CONTRIBUTION) < 1.0e-9
      REPORT "a'contribution = " & REAL'IMAGE(a'CONTRIBUTION) SEVERITY ERROR;
    ASSERT ABS(i_src + 0.25) < 1.0e-9
      REPORT "i_src = " & REAL'IMAGE(i_src) SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
