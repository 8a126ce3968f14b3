-- vams: stop 1 ms
--
-- SEAMS's dialect (the University of Cincinnati's tests): a nature declared without a
-- reference terminal. VHDL-AMS requires one (LRM 1076.1 4.8); vams gives it one without a
-- name, with a warning, reached as `electrical'reference` and as the default minus end of a
-- branch. A divider against the closed form.

PACKAGE electricalSystem IS
    NATURE electrical IS real ACROSS real THROUGH;
END PACKAGE electricalSystem;

USE work.electricalsystem.ALL;

ENTITY tb_unnamed_reference IS
END ENTITY tb_unnamed_reference;

ARCHITECTURE checked OF tb_unnamed_reference IS
    TERMINAL n1, n2 : electrical;
    QUANTITY vs ACROSS is_src THROUGH n1 TO electrical'reference;
    QUANTITY v1 ACROSS i1 THROUGH n1 TO n2;
    QUANTITY v2 ACROSS i2 THROUGH n2;
BEGIN
    vs == 3.0;
    v1 == 100.0 * i1;
    v2 == 200.0 * i2;

    check : PROCESS IS
    BEGIN
        WAIT FOR 0.5 ms;
        ASSERT abs(v2 - 2.0) < 1.0e-9 REPORT "v2 = " & real'image(v2) & ", not 2.0"
            SEVERITY error;
        ASSERT abs(is_src + 0.01) < 1.0e-12 REPORT "the source delivers 10 mA" SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
