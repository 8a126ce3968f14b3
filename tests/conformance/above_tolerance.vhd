-- vams: stop 3 ms
--
-- A threshold crossing is located to within the quantity's tolerance (its group's absolute
-- tolerance; 1e-9 for a `real` quantity): `'above` changes once the quantity is that far
-- past the level on the other side. A ripple of 1e-12 around its level never crosses it
-- (within tolerance it sits on the level), so a quantity sitting on a threshold does not flip
-- its `'above` at every step; a ramp crosses at the time of the closed form, to within
-- 1e-9 / slope.

LIBRARY ieee;
USE ieee.math_real.ALL;

ENTITY tb_above_tolerance IS
END ENTITY tb_above_tolerance;

ARCHITECTURE checked OF tb_above_tolerance IS
  QUANTITY ripple, ramp : real;
  SIGNAL ripple_events, ramp_events : natural := 0;
  SIGNAL ramp_crossed : time := 0 ns;
BEGIN
  ripple == 1.0e-12 * sin(2.0 * math_pi * 1.0e3 * now);
  ramp == 1.0e3 * (now - 1.5e-3);

  count_ripple : PROCESS IS
  BEGIN
    WAIT ON ripple'above(0.0);
    ripple_events <= ripple_events + 1;
  END PROCESS count_ripple;

  count_ramp : PROCESS IS
  BEGIN
    WAIT ON ramp'above(0.0);
    ramp_events <= ramp_events + 1;
    ramp_crossed <= now;
  END PROCESS count_ramp;

  check : PROCESS IS
  BEGIN
    WAIT FOR 3 ms;
    ASSERT ripple_events = 0
      REPORT "a ripple within tolerance flipped 'above " & integer'image(ripple_events) & " times"
      SEVERITY error;
    ASSERT ramp_events = 1
      REPORT "the ramp crossed " & integer'image(ramp_events) & " times" SEVERITY error;
    ASSERT abs(ramp_crossed - 1.5 ms) <= 1 ns
      REPORT "the ramp crossed at " & time'image(ramp_crossed) SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE checked;
