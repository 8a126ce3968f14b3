-- vams: stop 1 ms
--
-- A configuration instantiated like an entity (LRM 9.6: `u : CONFIGURATION work.cfg PORT
-- MAP (...)`), as the book's case studies do for their gate-level and device-level views:
-- the instance takes the configuration's entity, its architecture and the bindings it gives.
-- r_top is the ideal leg (1 Ohm) through cfg_leg_ideal, r_bottom the default binding (the
-- last architecture, twice its generic: 2 Ohm), so the midpoint of the 1 V divider sits at
-- 2/3 V.

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY resistive_leg IS
  GENERIC (r : REAL := 1.0);
  PORT (TERMINAL p, n : ELECTRICAL);
END ENTITY resistive_leg;

ARCHITECTURE ideal OF resistive_leg IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == r * i;
END ARCHITECTURE ideal;

ARCHITECTURE doubled OF resistive_leg IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == 2.0 * r * i;
END ARCHITECTURE doubled;

CONFIGURATION cfg_leg_ideal OF resistive_leg IS
  FOR ideal
  END FOR;
END CONFIGURATION cfg_leg_ideal;

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_configuration_instance IS
END ENTITY tb_configuration_instance;

ARCHITECTURE test OF tb_configuration_instance IS
  TERMINAL top, mid : ELECTRICAL;
  QUANTITY vs ACROSS is_src THROUGH top TO ELECTRICAL_REF;
  QUANTITY vmid ACROSS mid TO ELECTRICAL_REF;
BEGIN
  vs == 1.0;
  r_top : CONFIGURATION work.cfg_leg_ideal
    GENERIC MAP (r => 1.0)
    PORT MAP (p => top, n => mid);
  r_bottom : ENTITY work.resistive_leg
    GENERIC MAP (r => 1.0)
    PORT MAP (p => mid, n => ELECTRICAL_REF);

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(vmid - 2.0 / 3.0) < 1.0e-9
      REPORT "midpoint at " & REAL'IMAGE(vmid) & " V, expected 2/3 V" SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
