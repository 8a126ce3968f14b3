-- vams: stop 1 ms
--
-- A configuration declaration, as textbooks write them: the testbench's components are bound
-- by `configuration cfg_mixed of tb_configuration_declaration`, selected with
-- `--top cfg_mixed`: r1 to the ideal resistor (1 Ohm), r2 to one of twice its generic
-- (2 Ohm), so the midpoint of the 1 V divider sits at 2/3 V. The testbench alone (default
-- binding: the last architecture, `doubled`, for both) puts it at 1/2 V, which its own check
-- expects; tests/it/run.rs checks the configured midpoint.

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY divider_leg IS
  GENERIC (r : REAL := 1.0);
  PORT (TERMINAL p, n : ELECTRICAL);
END ENTITY divider_leg;

ARCHITECTURE ideal OF divider_leg IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == r * i;
END ARCHITECTURE ideal;

ARCHITECTURE doubled OF divider_leg IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == 2.0 * r * i;
END ARCHITECTURE doubled;

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_configuration_declaration IS
END ENTITY tb_configuration_declaration;

ARCHITECTURE test OF tb_configuration_declaration IS
  COMPONENT divider_leg IS
    GENERIC (r : REAL := 1.0);
    PORT (TERMINAL p, n : ELECTRICAL);
  END COMPONENT divider_leg;
  TERMINAL top, mid : ELECTRICAL;
  QUANTITY vs ACROSS is_src THROUGH top TO ELECTRICAL_REF;
  QUANTITY vmid ACROSS mid TO ELECTRICAL_REF;
BEGIN
  vs == 1.0;
  r1 : divider_leg GENERIC MAP (r => 1.0) PORT MAP (p => top, n => mid);
  r2 : divider_leg GENERIC MAP (r => 1.0) PORT MAP (p => mid, n => ELECTRICAL_REF);

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(vmid - 0.5) < 1.0e-9
      REPORT "default binding: midpoint at " & REAL'IMAGE(vmid) & " V, expected 1/2 V"
      SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;

CONFIGURATION cfg_mixed OF tb_configuration_declaration IS
  FOR test
    FOR r1 : divider_leg
      USE ENTITY work.divider_leg(ideal);
    END FOR;
    FOR OTHERS : divider_leg
      USE ENTITY work.divider_leg(doubled);
    END FOR;
  END FOR;
END CONFIGURATION cfg_mixed;

-- An incremental binding (LRM 5.2.1.1): no entity aspect, only a generic map, so r2 keeps
-- its default binding (`doubled`) with r => 3.0: 2 Ohm over 6 Ohm, the midpoint at 3/4 V.
CONFIGURATION cfg_incremental OF tb_configuration_declaration IS
  FOR test
    FOR r2 : divider_leg
      GENERIC MAP (r => 3.0);
    END FOR;
  END FOR;
END CONFIGURATION cfg_incremental;
