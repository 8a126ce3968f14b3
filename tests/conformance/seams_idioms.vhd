-- vams: stop 300 ms
--
-- The idioms of the University of Cincinnati's SEAMS test suite (VESTs, `ad-hoc/fromUC`):
-- a package that declares the elementary functions without a body (SEAMS computed them
-- natively; vams does the same, with a warning), the nature's reference terminal named
-- `electrical'reference`, time as a number through `time'pos(now)`, a second-order
-- equation started by `break x => ..., x'dot => ...`, and a constant computed by a
-- function of the generics.

PACKAGE electricalSystem IS
    NATURE electrical IS real ACROSS real THROUGH ground REFERENCE;
    FUNCTION SIN(X : real) RETURN real;
    FUNCTION EXP(X : real) RETURN real;
    FUNCTION POW(X, Y : real) RETURN real;
END PACKAGE electricalSystem;

USE work.electricalsystem.ALL;

ENTITY tb_seams_idioms IS
    GENERIC (w : real := 2.0; r : real := 100.0);
END ENTITY tb_seams_idioms;

ARCHITECTURE checked OF tb_seams_idioms IS
    FUNCTION squared (x : real) RETURN real IS
    BEGIN
        ASSERT x > 0.0 REPORT "a positive frequency is needed";
        RETURN pow(x, 2.0);
    END FUNCTION squared;

    CONSTANT w2 : real := squared(w);
    TERMINAL t1 : electrical;
    QUANTITY vs ACROSS i_src THROUGH t1 TO electrical'reference;
    QUANTITY vr ACROSS ir THROUGH t1 TO ground;
    QUANTITY x, decay : real;
BEGIN
    -- 50 Hz: time'pos(now) counts femtoseconds.
    esource : vs == 2.0 * sin(2.0 * 3.141592653589793 * 50.0 * real(time'pos(now)) * 1.0e-15);
    eres : vr == ir * r;
    edecay : decay == exp(-5.0 * real(time'pos(now)) * 1.0e-15);

    -- x'' = -w^2 x from x = 0, x' = 1: x = sin(w t) / w.
    BREAK x => 0.0, x'dot => 1.0;
    x'dot'dot == -w2 * x;

    check : PROCESS IS
        CONSTANT t : real := 0.3;
    BEGIN
        WAIT FOR 300 ms;
        ASSERT abs(x - sin(w * t) / w) < 2.0e-3
            REPORT "x = " & real'image(x) & ", expected " & real'image(sin(w * t) / w)
            SEVERITY error;
        ASSERT abs(ir - 2.0 * sin(2.0 * 3.141592653589793 * 50.0 * t) / r) < 1.0e-6
            REPORT "ir = " & real'image(ir) SEVERITY error;
        ASSERT abs(decay - exp(-5.0 * t)) < 1.0e-3
            REPORT "decay = " & real'image(decay) SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
