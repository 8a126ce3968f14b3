-- vams: stop 1 ms
--
-- The subtypes of a nature as type marks in expressions: a conversion to `N'across`, a
-- qualified expression of `N'through`, their scalar attributes, and the subtypes of an
-- array nature (`real_vector` subtypes with the nature's bounds).

LIBRARY ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;

ENTITY tb_nature_subtypes IS
END ENTITY tb_nature_subtypes;

ARCHITECTURE checked OF tb_nature_subtypes IS
    SUBNATURE bus4 IS electrical_vector(1 TO 4);
    CONSTANT gain : real := 2.0;
    QUANTITY v : electrical'ACROSS;
    QUANTITY i : electrical'THROUGH;
BEGIN
    v == electrical'ACROSS(gain) + electrical'THROUGH'(1.0);
    i == v * 1.0e-3;

    check : PROCESS IS
        VARIABLE volts : bus4'ACROSS := (OTHERS => 0.5);
    BEGIN
        WAIT FOR 0.5 ms;
        ASSERT v = 3.0 REPORT "v is not 3.0" SEVERITY error;
        ASSERT abs(i - 3.0e-3) < 1.0e-12 REPORT "i is not 3 mA" SEVERITY error;
        ASSERT electrical'ACROSS'HIGH = real'HIGH REPORT "across'high" SEVERITY error;
        ASSERT volts'LENGTH = 4 AND volts(4) = 0.5 REPORT "bus4'across" SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
