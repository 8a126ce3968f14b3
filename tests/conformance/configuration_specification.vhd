-- vams: stop 1 ms
--
-- Configuration specifications, as textbooks write them: a component bound to an entity
-- and architecture other than the default, by instance label and by `others`.
-- A 1 V source across two resistors of the same component: r1 is bound to the ideal
-- resistor (1 Ohm), r2 (by `others`) to a resistor of twice its generic (2 Ohm), so the
-- midpoint sits at 2/3 V. Default binding would take the last architecture for both (1/2 V).

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY resistor IS
  GENERIC (r : REAL := 1.0);
  PORT (TERMINAL p, n : ELECTRICAL);
END ENTITY resistor;

ARCHITECTURE ideal OF resistor IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == r * i;
END ARCHITECTURE ideal;

ARCHITECTURE doubled OF resistor IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == 2.0 * r * i;
END ARCHITECTURE doubled;

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_configuration_specification IS
END ENTITY tb_configuration_specification;

ARCHITECTURE test OF tb_configuration_specification IS
  COMPONENT resistor IS
    GENERIC (r : REAL := 1.0);
    PORT (TERMINAL p, n : ELECTRICAL);
  END COMPONENT resistor;
  FOR r1 : resistor USE ENTITY work.resistor(ideal);
  FOR OTHERS : resistor USE ENTITY work.resistor(doubled);
  TERMINAL top, mid : ELECTRICAL;
  QUANTITY vs ACROSS is_src THROUGH top TO ELECTRICAL_REF;
  QUANTITY vmid ACROSS mid TO ELECTRICAL_REF;
BEGIN
  vs == 1.0;
  r1 : resistor GENERIC MAP (r => 1.0) PORT MAP (p => top, n => mid);
  r2 : resistor GENERIC MAP (r => 1.0) PORT MAP (p => mid, n => ELECTRICAL_REF);

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(vmid - 2.0 / 3.0) < 1.0e-9
      REPORT "midpoint at " & REAL'IMAGE(vmid) & " V, expected 2/3 V"
      SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
