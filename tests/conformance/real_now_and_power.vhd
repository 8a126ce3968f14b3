-- vams: stop 2 ms
--
-- VHDL-AMS's second NOW, `impure function now return real` (LRM 1076.1 14.2), chosen where
-- a real is expected (a function's real parameter, a real expression), beside the `time`
-- one; and math_real's `"**"` of a real or integer base and a real exponent, in a process
-- and in an equation (the book's case studies switch resistances as 10 ** log10_r).

LIBRARY ieee;
USE ieee.math_real.ALL;

ENTITY tb_real_now_and_power IS
END ENTITY tb_real_now_and_power;

ARCHITECTURE test OF tb_real_now_and_power IS
  QUANTITY log10_r : real;
  QUANTITY r : real;

  FUNCTION seconds_until (t : real; deadline : real) RETURN real IS
  BEGIN
    RETURN deadline - t;
  END FUNCTION seconds_until;
BEGIN
  log10_r == 3.0;
  r == 10 ** log10_r;

  check : PROCESS IS
    VARIABLE left_s : real;
  BEGIN
    WAIT FOR 1 ms;
    left_s := seconds_until(NOW, 1.5e-3);
    ASSERT ABS(left_s - 0.5e-3) < 1.0e-12
      REPORT "real NOW: " & real'IMAGE(left_s) SEVERITY error;
    ASSERT NOW = 1 ms REPORT "time NOW" SEVERITY error;
    ASSERT ABS(2.0 ** 0.5 - sqrt(2.0)) < 1.0e-12 REPORT "real ** real" SEVERITY error;
    ASSERT ABS(2 ** 0.5 - sqrt(2.0)) < 1.0e-12 REPORT "integer ** real" SEVERITY error;
    ASSERT ABS(r - 1000.0) < 1.0e-6 REPORT "10 ** log10_r = " & real'IMAGE(r) SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
