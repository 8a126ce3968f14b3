-- vams: stop 1 sec
--
-- Simultaneous procedural statements (LRM 1076.1 15.4): sequential code computing
-- quantities, equivalent to one equation per quantity assigned. `x` ramps from -2 to 2; one
-- procedural clips it and sums a power series by a loop, another reads its target before
-- assigning it (`w := 0.5 * w + 1.0`, an implicit equation whose solution is w = 2).

ENTITY tb_procedural IS
END ENTITY tb_procedural;

ARCHITECTURE test OF tb_procedural IS
  QUANTITY x, clipped, series : REAL;
  QUANTITY w : REAL;
BEGIN
  x == -2.0 + 4.0 * NOW;

  PROCEDURAL IS
    VARIABLE term, acc : REAL := 0.0;
  BEGIN
    IF x > 1.0 THEN
      clipped := 1.0;
    ELSIF x < -1.0 THEN
      clipped := -1.0;
    ELSE
      clipped := x;
    END IF;
    -- 1 + x + x**2 + x**3
    term := 1.0;
    acc := 0.0;
    FOR k IN 0 TO 3 LOOP
      acc := acc + term;
      term := term * x;
    END LOOP;
    series := acc;
  END PROCEDURAL;

  fixed_point : PROCEDURAL IS
  BEGIN
    w := 0.5 * w + 1.0;
  END PROCEDURAL fixed_point;

  check : PROCESS IS
    TYPE points IS ARRAY (1 TO 5) OF REAL;
    CONSTANT at_x : points := (-1.5, -0.5, 0.0, 0.5, 1.5);
    VARIABLE elapsed, t, xv, c : REAL := 0.0;
  BEGIN
    FOR k IN points'RANGE LOOP
      t := (at_x(k) + 2.0) / 4.0;
      WAIT FOR (t - elapsed) * 1 sec;
      elapsed := t;
      xv := at_x(k);
      IF xv > 1.0 THEN
        c := 1.0;
      ELSIF xv < -1.0 THEN
        c := -1.0;
      ELSE
        c := xv;
      END IF;
      ASSERT abs(clipped - c) < 1.0e-9
        REPORT "clipped = " & REAL'IMAGE(clipped) & " at x = " & REAL'IMAGE(xv) SEVERITY error;
      ASSERT abs(series - (1.0 + xv + xv * xv + xv * xv * xv)) < 1.0e-9
        REPORT "series = " & REAL'IMAGE(series) & " at x = " & REAL'IMAGE(xv) SEVERITY error;
      ASSERT abs(w - 2.0) < 1.0e-9 REPORT "w = " & REAL'IMAGE(w) SEVERITY error;
    END LOOP;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
