-- vams: stop 1 ms
--
-- Aggregates with named choices in equations of quantity arrays: a choice by index and by
-- range, `others` filling the rest of the other side's bounds (ascending and descending), and
-- named choices alone, whose bounds are their own (ascending). Each element is placed by
-- its index, not by its position in the aggregate (LRM 7.3.2.2).

ENTITY tb_named_choice_equations IS
END ENTITY tb_named_choice_equations;

ARCHITECTURE checked OF tb_named_choice_equations IS
    QUANTITY v : real_vector(1 TO 4);
    QUANTITY w : real_vector(3 DOWNTO 0);
    QUANTITY u : real_vector(0 TO 2);
    QUANTITY ramp : real;
BEGIN
    ramp == 1.0e3 * now;
    v == (4 => 4.0, 2 => 2.0, OTHERS => 1.0);
    w == (0 => 10.0, 2 TO 3 => ramp, OTHERS => -1.0);
    u == (2 => 5.0, 0 TO 1 => 7.0);

    check : PROCESS IS
    BEGIN
        WAIT FOR 0.5 ms;
        ASSERT v(1) = 1.0 AND v(2) = 2.0 AND v(3) = 1.0 AND v(4) = 4.0
            REPORT "v is not (1, 2, 1, 4)" SEVERITY error;
        ASSERT w(0) = 10.0 AND w(1) = -1.0 REPORT "w(0 to 1) is not (10, -1)" SEVERITY error;
        ASSERT abs(w(2) - 0.5) < 1.0e-9 AND abs(w(3) - 0.5) < 1.0e-9
            REPORT "w(2) and w(3) do not follow the ramp" SEVERITY error;
        ASSERT u(0) = 7.0 AND u(1) = 7.0 AND u(2) = 5.0
            REPORT "u is not (7, 7, 5)" SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
