-- vams: stop 2 ms
--
-- Simple simultaneous statements of composite type (LRM 1076.1 15.1): one equation per
-- scalar subelement. Quantity arrays equated with aggregates (with `others`), with slices of
-- other arrays and with a function returning an array; `'dot` of an array, on three
-- independent RC sections charging from 1, 2 and 3 V: v_k(t) = k (1 - exp(-t / RC)).

LIBRARY ieee;
USE ieee.math_real.ALL;

ENTITY tb_composite_equations IS
END ENTITY tb_composite_equations;

ARCHITECTURE test OF tb_composite_equations IS
  CONSTANT rc : real := 1.0e-3;
  FUNCTION ramp_targets (t : real) RETURN real_vector IS
    VARIABLE result : real_vector(1 TO 3);
  BEGIN
    FOR k IN result'RANGE LOOP
      result(k) := real(k) * t;
    END LOOP;
    RETURN result;
  END FUNCTION ramp_targets;

  QUANTITY v : real_vector(1 TO 3);
  QUANTITY src : real_vector(1 TO 3);
  QUANTITY zeros : real_vector(0 TO 4);
  QUANTITY tail : real_vector(0 TO 1);
  QUANTITY ramps : real_vector(1 TO 3);
BEGIN
  src == (1.0, 2.0, 3.0);
  tail == src(2 TO 3);
  ramps == ramp_targets(NOW);
  -- rc * v'dot == src - v, element by element, from v = 0 (the textbook initial
  -- condition: each branch of the simultaneous if gives three equations).
  IF DOMAIN = QUIESCENT_DOMAIN USE
    v == (OTHERS => 0.0);
  ELSE
    v'DOT == ((src(1) - v(1)) / rc, (src(2) - v(2)) / rc, (src(3) - v(3)) / rc);
  END USE;
  -- An array determined by two slices.
  zeros(0 TO 2) == (0.0, 0.0, 0.0);
  zeros(3 TO 4) == (OTHERS => 0.0);

  check : PROCESS IS
    VARIABLE t : real;
  BEGIN
    FOR n IN 1 TO 4 LOOP
      WAIT FOR 0.5 ms;
      t := real(n) * 0.5e-3;
      FOR k IN 1 TO 3 LOOP
        -- Within 1 % at the default tolerance (a global error, accumulated over the steps).
        ASSERT abs(v(k) - real(k) * (1.0 - exp(-t / rc))) < 1.0e-2 * real(k)
          REPORT "v(" & integer'IMAGE(k) & ") = " & real'IMAGE(v(k)) SEVERITY failure;
        ASSERT abs(ramps(k) - real(k) * t) < 1.0e-12 REPORT "ramps" SEVERITY failure;
      END LOOP;
      ASSERT tail(0) = 2.0 AND tail(1) = 3.0 REPORT "slice" SEVERITY failure;
      ASSERT zeros(4) = 0.0 REPORT "others" SEVERITY failure;
    END LOOP;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
