-- vams: stop 1 ms
--
-- Slices of a terminal array: as port actuals (`t => n(1 to 2)`, a two-terminal port
-- connected to half of a bus) and as the ends of a branch (`quantity d across n(1 to 2)
-- to n(3 to 4)`, an array of two branch quantities). Each source pair drives its two
-- terminals to v0 and 2 v0, so the bus is at 1, 2, 3 and 6 V.

LIBRARY IEEE_PROPOSED;
USE IEEE_PROPOSED.ELECTRICAL_SYSTEMS.ALL;

ENTITY source_pair IS
  GENERIC (v0 : REAL);
  PORT (TERMINAL t : ELECTRICAL_VECTOR(1 TO 2));
END ENTITY source_pair;

ARCHITECTURE ideal OF source_pair IS
  QUANTITY v ACROSS i THROUGH t TO ELECTRICAL_REF;
BEGIN
  v(1) == v0;
  v(2) == 2.0 * v0;
END ARCHITECTURE ideal;

LIBRARY IEEE_PROPOSED;
USE IEEE_PROPOSED.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_terminal_slices IS
END ENTITY tb_terminal_slices;

ARCHITECTURE test OF tb_terminal_slices IS
  TERMINAL n : ELECTRICAL_VECTOR(1 TO 4);
  QUANTITY bus_v ACROSS n TO ELECTRICAL_REF;
  QUANTITY d ACROSS n(1 TO 2) TO n(3 TO 4);
BEGIN
  low : ENTITY work.source_pair(ideal) GENERIC MAP (v0 => 1.0) PORT MAP (t => n(1 TO 2));
  high : ENTITY work.source_pair(ideal) GENERIC MAP (v0 => 3.0) PORT MAP (t => n(3 TO 4));

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(bus_v(1) - 1.0) < 1.0e-9 AND ABS(bus_v(2) - 2.0) < 1.0e-9
      AND ABS(bus_v(3) - 3.0) < 1.0e-9 AND ABS(bus_v(4) - 6.0) < 1.0e-9
      REPORT "bus at " & REAL'IMAGE(bus_v(1)) & ", " & REAL'IMAGE(bus_v(2)) & ", "
        & REAL'IMAGE(bus_v(3)) & ", " & REAL'IMAGE(bus_v(4))
      SEVERITY ERROR;
    ASSERT ABS(d(1) + 2.0) < 1.0e-9 AND ABS(d(2) + 4.0) < 1.0e-9
      REPORT "d = " & REAL'IMAGE(d(1)) & ", " & REAL'IMAGE(d(2)) SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
