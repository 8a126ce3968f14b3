-- vams: stop 1 ms
--
-- A binding indication with its own generic and port maps: the component `leg` (generic
-- `value`, ports `a`, `b`) is bound to the entity `two_terminal_resistor` (generic `r`, ports
-- `p`, `n`) with `r => 2.0 * value`, `p => a`, `n => b`. With value 1.0 and 0.5 on the upper
-- and lower legs of a 1 V divider, the legs are 2 and 1 Ohm: the midpoint sits at 1/3 V.

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY two_terminal_resistor IS
  GENERIC (r : REAL := 1.0);
  PORT (TERMINAL p, n : ELECTRICAL);
END ENTITY two_terminal_resistor;

ARCHITECTURE ideal OF two_terminal_resistor IS
  QUANTITY v ACROSS i THROUGH p TO n;
BEGIN
  v == r * i;
END ARCHITECTURE ideal;

LIBRARY IEEE;
USE IEEE.ELECTRICAL_SYSTEMS.ALL;

ENTITY tb_binding_maps IS
END ENTITY tb_binding_maps;

ARCHITECTURE test OF tb_binding_maps IS
  COMPONENT leg IS
    GENERIC (value : REAL := 1.0);
    PORT (TERMINAL a, b : ELECTRICAL);
  END COMPONENT leg;
  FOR ALL : leg USE ENTITY work.two_terminal_resistor(ideal)
    GENERIC MAP (r => 2.0 * value)
    PORT MAP (p => a, n => b);
  TERMINAL top, mid : ELECTRICAL;
  QUANTITY vs ACROSS is_src THROUGH top TO ELECTRICAL_REF;
  QUANTITY vmid ACROSS mid TO ELECTRICAL_REF;
BEGIN
  vs == 1.0;
  upper : leg PORT MAP (a => top, b => mid);                       -- value defaults to 1.0
  lower : leg GENERIC MAP (0.5) PORT MAP (mid, ELECTRICAL_REF);      -- positional

  check : PROCESS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT ABS(vmid - 1.0 / 3.0) < 1.0e-9
      REPORT "midpoint at " & REAL'IMAGE(vmid) & " V, expected 1/3 V"
      SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
