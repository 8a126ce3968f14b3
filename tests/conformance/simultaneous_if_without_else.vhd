-- vams: stop 10 ms
--
-- A simultaneous if without `else` whose conditions cover every case, as device models of
-- the SEAMS test suite write their junctions (`if v > -5.0 * vt use ... elsif v <= -5.0 * vt
-- use ... end use;`): a diode, exponential above -5 Vt and linear below, in series with a
-- resistor, driven by a ramp from -1 V to 1 V. The current is checked against the
-- junction's own equation at the solved voltage (to 1e-4 of itself: the solver's residual
-- test at the default tolerance), and Kirchhoff's laws.

LIBRARY ieee;
USE ieee.math_real.ALL;
USE ieee.electrical_systems.ALL;

ENTITY tb_simultaneous_if_without_else IS
END ENTITY tb_simultaneous_if_without_else;

ARCHITECTURE checked OF tb_simultaneous_if_without_else IS
  CONSTANT isat : real := 1.0e-12;
  CONSTANT vt : real := 0.025;
  CONSTANT r : real := 1.0e3;
  TERMINAL anode, supply : electrical;
  QUANTITY vsrc ACROSS isrc THROUGH supply;
  QUANTITY vr ACROSS ir THROUGH supply TO anode;
  QUANTITY vd ACROSS id THROUGH anode;
BEGIN
  source : vsrc == -1.0 + 200.0 * now;
  resistor : vr == ir * r;
  junction : IF vd > -5.0 * vt USE
    id == isat * (exp(vd / vt) - 1.0);
  ELSIF vd <= -5.0 * vt USE
    id == isat * (exp(-5.0) - 1.0) + isat * exp(-5.0) / vt * (vd + 5.0 * vt);
  END USE;
  BREAK ON vd'above(-5.0 * vt);

  check : PROCESS IS
    VARIABLE expected : real;
  BEGIN
    FOR k IN 1 TO 9 LOOP
      WAIT FOR 1 ms;
      IF vd > -5.0 * vt THEN
        expected := isat * (exp(vd / vt) - 1.0);
      ELSE
        expected := isat * (exp(-5.0) - 1.0) + isat * exp(-5.0) / vt * (vd + 5.0 * vt);
      END IF;
      ASSERT abs(id - expected) <= 1.0e-4 * abs(expected) + 1.0e-15
        REPORT "junction current " & real'image(id) & ", expected " & real'image(expected)
        SEVERITY error;
      ASSERT abs(vsrc - vr - vd) < 1.0e-9 AND abs(ir - id) < 1.0e-12
        REPORT "Kirchhoff's laws do not hold" SEVERITY error;
    END LOOP;
    -- At 9 ms the source is at 0.8 V: the diode conducts, a few hundred microamperes.
    ASSERT id > 1.0e-4 REPORT "the diode does not conduct at 0.8 V" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE checked;
