-- vams: stop 1 ms
--
-- A whole quantity array as the argument of a function, in an equation and in a process, as
-- the book writes it (`scaled_position == vector_multiply(source_position, scale_factor);`):
-- the array of its quantities' values, of type `real_vector` with the array's bounds.

ENTITY tb_quantity_array_arguments IS
END ENTITY tb_quantity_array_arguments;

ARCHITECTURE checked OF tb_quantity_array_arguments IS
    FUNCTION vector_multiply (p : real_vector; r : real) RETURN real_vector IS
        VARIABLE result : real_vector(p'RANGE);
    BEGIN
        FOR index IN p'RANGE LOOP
            result(index) := p(index) * r;
        END LOOP;
        RETURN result;
    END FUNCTION vector_multiply;

    FUNCTION total (p : real_vector) RETURN real IS
        VARIABLE sum : real := 0.0;
    BEGIN
        FOR index IN p'RANGE LOOP
            sum := sum + p(index);
        END LOOP;
        RETURN sum;
    END FUNCTION total;

    QUANTITY scale_factor : real;
    QUANTITY source_position, scaled_position : real_vector(1 TO 3);
    QUANTITY sum_of_source : real;
BEGIN
    source_position == (1.0, 2.0, 1.0e3 * now);
    scale_factor == 2.0;
    scaled_position == vector_multiply(source_position, scale_factor);
    sum_of_source == total(source_position);

    check : PROCESS IS
    BEGIN
        WAIT FOR 0.5 ms;
        ASSERT scaled_position(1) = 2.0 AND scaled_position(2) = 4.0
            REPORT "scaled_position(1 to 2)" SEVERITY error;
        ASSERT abs(scaled_position(3) - 1.0) < 1.0e-9 REPORT "scaled_position(3)" SEVERITY error;
        ASSERT abs(sum_of_source - 3.5) < 1.0e-9 REPORT "sum_of_source" SEVERITY error;
        ASSERT abs(total(source_position) - 3.5) < 1.0e-9 REPORT "total in a process" SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
