-- vams: stop 2 sec
--
-- Derivatives assigned in a simultaneous procedural, as the book's state-space motor model
-- writes them (`x(1)'dot := sum(1);`): each `q'dot := e` is the equation `q'dot == e`, and a
-- read of `q'dot` after the assignment reads the value assigned. A two-state cascade
-- x1' = -x1, x2' = x1 - x2 from x1 = 1, x2 = 0 has x1 = exp(-t), x2 = t exp(-t); a scalar
-- y' = -2 y from y = 1 has y = exp(-2 t).

LIBRARY ieee;
USE ieee.math_real.ALL;

ENTITY tb_procedural_derivatives IS
END ENTITY tb_procedural_derivatives;

ARCHITECTURE checked OF tb_procedural_derivatives IS
    TYPE real_matrix IS ARRAY (1 TO 2, 1 TO 2) OF real;
    CONSTANT a : real_matrix := ((-1.0, 0.0), (1.0, -1.0));
    QUANTITY x : real_vector(1 TO 2);
    QUANTITY y, slope : real;
BEGIN
    state_eqn : PROCEDURAL IS
        VARIABLE sum : real_vector(1 TO 2) := (0.0, 0.0);
    BEGIN
        FOR i IN 1 TO 2 LOOP
            FOR j IN 1 TO 2 LOOP
                sum(i) := sum(i) + a(i, j) * x(j);
            END LOOP;
        END LOOP;
        x(1)'DOT := sum(1);
        x(2)'DOT := sum(2);
    END PROCEDURAL state_eqn;

    decay : PROCEDURAL IS
    BEGIN
        y'DOT := -2.0 * y;
        slope := y'DOT;
    END PROCEDURAL decay;

    BREAK x(1) => 1.0, x(2) => 0.0, y => 1.0;

    check : PROCESS IS
        VARIABLE t : real;
    BEGIN
        FOR k IN 1 TO 4 LOOP
            WAIT FOR 0.5 sec;
            t := 0.5 * real(k);
            ASSERT abs(x(1) - exp(-t)) < 1.0e-3 REPORT "x(1) at " & real'IMAGE(t) SEVERITY error;
            ASSERT abs(x(2) - t * exp(-t)) < 1.0e-3 REPORT "x(2) at " & real'IMAGE(t) SEVERITY error;
            ASSERT abs(y - exp(-2.0 * t)) < 1.0e-3 REPORT "y at " & real'IMAGE(t) SEVERITY error;
            ASSERT abs(slope + 2.0 * y) < 1.0e-9 REPORT "slope at " & real'IMAGE(t) SEVERITY error;
        END LOOP;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
