-- vams: stop 1 sec
--
-- The case studies' piecewise-linear characteristic (The System Designer's Guide to VHDL-AMS,
-- the RC airplane's propeller): a package function with a binary search over unconstrained
-- `real_vector` parameters (`xdata'right`), helper functions with assertions, extrapolation
-- beyond both ends, called from an equation with the tables an instance passes as generics.
-- The operand ramps from 0 to 12 over the run; the function is checked at points with a
-- closed form, inside the table (on a flat segment too) and beyond both ends. Expanded
-- naively, the search's paths include ones no operand can take (every comparison true, past
-- the checks that returned early), where `ydata(mid + 1)` runs off the table: what the paths
-- taken so far say about `x` must prune them.

PACKAGE pwl_functions IS
  FUNCTION pwl_dim1_extrap (x : IN REAL; xdata, ydata : IN REAL_VECTOR) RETURN REAL;
END PACKAGE pwl_functions;

PACKAGE BODY pwl_functions IS
  FUNCTION interpolate (x, y2, y1, x2, x1 : IN REAL) RETURN REAL IS
    VARIABLE m, yvalue : REAL;
  BEGIN
    ASSERT (x1 /= x2)
      REPORT "interpolate: x1 cannot be equal to x2"
      SEVERITY error;
    ASSERT (x >= x1) AND (x <= x2)
      REPORT "interpolate: x must be between x1 and x2, inclusively "
      SEVERITY error;
    m := (y2 - y1) / (x2 - x1);
    yvalue := y1 + m * (x - x1);
    RETURN yvalue;
  END FUNCTION interpolate;

  FUNCTION extrapolate (x, y2, y1, x2, x1 : IN REAL) RETURN REAL IS
    VARIABLE m, yvalue : REAL;
  BEGIN
    m := (y2 - y1) / (x2 - x1);
    yvalue := y1 + m * (x - x1);
    RETURN yvalue;
  END FUNCTION extrapolate;

  FUNCTION pwl_dim1_extrap (x : IN REAL; xdata, ydata : IN REAL_VECTOR) RETURN REAL IS
    VARIABLE yvalue : REAL;
    VARIABLE start, fin, mid : INTEGER;
  BEGIN
    IF x <= xdata(0) THEN
      yvalue := extrapolate(x, ydata(1), ydata(0), xdata(1), xdata(0));
      RETURN yvalue;
    END IF;
    IF x >= xdata(xdata'RIGHT) THEN
      yvalue := extrapolate(x, ydata(ydata'RIGHT), ydata(ydata'RIGHT - 1),
                            xdata(xdata'RIGHT), xdata(xdata'RIGHT - 1));
      RETURN yvalue;
    END IF;
    start := 0;
    fin := xdata'RIGHT;
    WHILE start <= fin LOOP
      mid := (start + fin) / 2;
      IF xdata(mid) < x THEN
        start := mid + 1;
      ELSE
        fin := mid - 1;
      END IF;
    END LOOP;
    IF xdata(mid) > x THEN
      mid := mid - 1;
    END IF;
    yvalue := interpolate(x, ydata(mid + 1), ydata(mid), xdata(mid + 1), xdata(mid));
    RETURN yvalue;
  END FUNCTION pwl_dim1_extrap;
END PACKAGE BODY pwl_functions;

ENTITY characteristic IS
  GENERIC (ydata : REAL_VECTOR; xdata : REAL_VECTOR);
  PORT (QUANTITY x : IN REAL; QUANTITY y : OUT REAL);
END ENTITY characteristic;

ARCHITECTURE table OF characteristic IS
  USE WORK.pwl_functions.ALL;
BEGIN
  y == pwl_dim1_extrap(x, xdata, ydata);
END ARCHITECTURE table;

ENTITY tb_pwl_table_generic IS
END ENTITY tb_pwl_table_generic;

ARCHITECTURE test OF tb_pwl_table_generic IS
  QUANTITY x, y : REAL;
BEGIN
  x == 12.0 * NOW;
  curve : ENTITY WORK.characteristic(table)
    GENERIC MAP (ydata => (1.0, 3.0, 4.0, 4.0, 2.0, 0.0),
                 xdata => (1.0, 2.0, 4.0, 6.0, 8.0, 10.0))
    PORT MAP (x => x, y => y);

  check : PROCESS IS
    TYPE points IS ARRAY (1 TO 6) OF REAL;
    -- Times, and the value expected there (x = 12 t): extrapolated below 1 (slope 2), inside,
    -- on the flat segment from 4 to 6, and extrapolated beyond 10 (slope -1).
    CONSTANT at_time : points := (0.025, 0.125, 0.25, 0.375, 0.75, 0.95);
    CONSTANT expect : points := (-0.4, 2.0, 3.5, 4.0, 1.0, -1.4);
    VARIABLE elapsed : REAL := 0.0;
  BEGIN
    FOR k IN points'RANGE LOOP
      WAIT FOR (at_time(k) - elapsed) * 1 sec;
      elapsed := at_time(k);
      ASSERT abs(y - expect(k)) < 1.0e-9
        REPORT "y = " & REAL'IMAGE(y) & " at x = " & REAL'IMAGE(x) & ", expected "
               & REAL'IMAGE(expect(k))
        SEVERITY error;
    END LOOP;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
