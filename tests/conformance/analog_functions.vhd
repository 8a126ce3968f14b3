-- vams: stop 1 sec
--
-- Functions with branches, loops and early returns called from simultaneous statements, the
-- way model libraries write them: a saturation, a polynomial by Horner's loop over a constant
-- coefficient table, and a piecewise-linear table looked up by binary search. `x` ramps from
-- -2 to 10 over the run, through every branch of each. A process checks each quantity at
-- points where the value is known in closed form, and everywhere against the same function
-- called from the process (run by the event kernel, not expanded into the equation). `z` is
-- found by Newton through the table, `pwl(z) == 0.3 + 3.0 * now`, so the derivative of the
-- expanded lookup must be exact: z = (0.3 + 3 t) / 2 while it is below 1, then 1 + (y - 2).

LIBRARY IEEE;
USE IEEE.MATH_REAL.ALL;

PACKAGE shapes IS
  CONSTANT xs : REAL_VECTOR(0 TO 4) := (0.0, 1.0, 2.0, 4.0, 8.0);
  CONSTANT ys : REAL_VECTOR(0 TO 4) := (0.0, 2.0, 3.0, 3.5, 3.0);
  CONSTANT coeffs : REAL_VECTOR(0 TO 3) := (1.0, -0.5, 0.25, 0.125);
  FUNCTION saturate (x, bound : REAL) RETURN REAL;
  FUNCTION poly (x : REAL) RETURN REAL;
  FUNCTION pwl (x : REAL) RETURN REAL;
END PACKAGE shapes;

PACKAGE BODY shapes IS
  FUNCTION saturate (x, bound : REAL) RETURN REAL IS
  BEGIN
    IF x > bound THEN
      RETURN bound;
    ELSIF x < -bound THEN
      RETURN -bound;
    END IF;
    RETURN x;
  END FUNCTION saturate;

  FUNCTION poly (x : REAL) RETURN REAL IS
    VARIABLE acc : REAL := 0.0;
  BEGIN
    FOR k IN 3 DOWNTO 0 LOOP
      acc := acc * x + coeffs(k);
    END LOOP;
    RETURN acc;
  END FUNCTION poly;

  FUNCTION pwl (x : REAL) RETURN REAL IS
    VARIABLE lo, hi, mid : INTEGER;
  BEGIN
    IF x <= xs(0) THEN
      RETURN ys(0);
    END IF;
    IF x >= xs(xs'HIGH) THEN
      RETURN ys(ys'HIGH);
    END IF;
    lo := 0;
    hi := xs'HIGH;
    WHILE hi - lo > 1 LOOP
      mid := (lo + hi) / 2;
      IF xs(mid) <= x THEN
        lo := mid;
      ELSE
        hi := mid;
      END IF;
    END LOOP;
    RETURN ys(lo) + (ys(hi) - ys(lo)) * (x - xs(lo)) / (xs(hi) - xs(lo));
  END FUNCTION pwl;
END PACKAGE BODY shapes;

USE WORK.shapes.ALL;

ENTITY tb_analog_functions IS
END ENTITY tb_analog_functions;

ARCHITECTURE test OF tb_analog_functions IS
  QUANTITY x : REAL;
  QUANTITY s, p, w : REAL;
  QUANTITY z : REAL := 0.5;
BEGIN
  pwl(z) == 0.3 + 3.0 * NOW;
  x == -2.0 + 12.0 * NOW;
  s == saturate(x, 1.5);
  p == poly(x);
  w == pwl(x);

  check : PROCESS IS
    VARIABLE xv : REAL;
  BEGIN
    -- Closed forms: x = 1 at 0.25 s, x = 4 at 0.5 s, x = 7 at 0.75 s.
    WAIT FOR 250 ms;
    ASSERT abs(s - 1.0) < 1.0e-9 REPORT "saturate(1.0) /= 1.0" SEVERITY error;
    ASSERT abs(p - 0.875) < 1.0e-9 REPORT "poly(1.0) /= 0.875" SEVERITY error;
    ASSERT abs(w - 2.0) < 1.0e-9 REPORT "pwl(1.0) /= 2.0" SEVERITY error;
    ASSERT abs(z - 0.525) < 1.0e-9 REPORT "z /= 0.525 at 0.25 s" SEVERITY error;
    WAIT FOR 250 ms;
    ASSERT abs(s - 1.5) < 1.0e-9 REPORT "saturate(4.0) /= 1.5" SEVERITY error;
    ASSERT abs(p - 11.0) < 1.0e-9 REPORT "poly(4.0) /= 11.0" SEVERITY error;
    ASSERT abs(w - 3.5) < 1.0e-9 REPORT "pwl(4.0) /= 3.5" SEVERITY error;
    ASSERT abs(z - 0.9) < 1.0e-9 REPORT "z /= 0.9 at 0.5 s" SEVERITY error;
    WAIT FOR 250 ms;
    ASSERT abs(w - 3.125) < 1.0e-9 REPORT "pwl(7.0) /= 3.125" SEVERITY error;
    ASSERT abs(z - 1.55) < 1.0e-9 REPORT "z /= 1.55 at 0.75 s" SEVERITY error;
    -- Everywhere else against the kernel's run of the same functions.
    FOR i IN 1 TO 24 LOOP
      WAIT FOR 10 ms;
      xv := x;
      ASSERT abs(xv - (-2.0 + 12.0 * (0.75 + REAL(i) * 0.01))) < 1.0e-9
        REPORT "x is off its ramp" SEVERITY error;
      ASSERT abs(s - saturate(xv, 1.5)) < 1.0e-9 REPORT "s /= saturate(x)" SEVERITY error;
      ASSERT abs(p - poly(xv)) < 1.0e-9 * abs(poly(xv)) REPORT "p /= poly(x)" SEVERITY error;
      ASSERT abs(w - pwl(xv)) < 1.0e-9 REPORT "w /= pwl(x)" SEVERITY error;
    END LOOP;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
