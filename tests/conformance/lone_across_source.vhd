-- vams: stop 5 ms
--
-- A source written as the University of Cincinnati's SEAMS test suite writes it: an across
-- quantity without a through quantity, set by an equation (`quantity vs across n1;
-- vs == ...;`). LRM 1076.1 12.6.6 counts one equation per through and free quantity, so the
-- equation is one too many; vams gives the branch an implicit through quantity (the source's
-- current) with a warning. A voltmeter (`vm`, an across quantity that no equation sets)
-- keeps no current. Checked against the RC closed form v(t) = 1 - exp(-t / RC) (the
-- capacitor discharged at the quiescent point) and a controlled source (`vout == 2 * vm`)
-- into a load.

PACKAGE electricalSystem IS
    NATURE electrical IS real ACROSS real THROUGH ground REFERENCE;
END PACKAGE electricalSystem;

USE work.electricalsystem.ALL;
LIBRARY ieee;
USE ieee.math_real.ALL;

ENTITY tb_lone_across_source IS
END ENTITY tb_lone_across_source;

ARCHITECTURE checked OF tb_lone_across_source IS
    TERMINAL n1, n2, n3 : electrical;
    CONSTANT r : real := 1.0e3;
    CONSTANT c : real := 1.0e-6;
    CONSTANT rl : real := 500.0;
    QUANTITY vs ACROSS n1;
    QUANTITY vr ACROSS ir THROUGH n1 TO n2;
    QUANTITY vc ACROSS ic THROUGH n2;
    QUANTITY vm ACROSS n2;
    QUANTITY vout ACROSS n3;
    QUANTITY vl ACROSS il THROUGH n3;
BEGIN
    src : vs == 1.0;
    res : vr == ir * r;
    IF domain = quiescent_domain USE
        vc == 0.0;
    ELSE
        ic == c * vc'dot;
    END USE;
    vcvs : vout == 2.0 * vm;
    load : vl == il * rl;

    check : PROCESS IS
        VARIABLE expected : real;
    BEGIN
        WAIT FOR 1 ms;
        expected := 1.0 - exp(-1.0e-3 / (r * c));
        ASSERT abs(vc - expected) < 2.0e-3
            REPORT "vc(RC) = " & real'image(vc) & ", expected " & real'image(expected)
            SEVERITY error;
        ASSERT abs(vm - vc) < 1.0e-12 REPORT "the voltmeter reads the capacitor" SEVERITY error;
        ASSERT abs(ir - (1.0 - vc) / r) < 1.0e-9
            REPORT "the source drives the resistor's current" SEVERITY error;
        ASSERT abs(il - 2.0 * vc / rl) < 1.0e-9
            REPORT "the controlled source drives the load" SEVERITY error;
        WAIT FOR 4 ms;
        ASSERT abs(vc - (1.0 - exp(-5.0))) < 2.0e-3 REPORT "vc(5 RC)" SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
