-- vams: stop 10 ms
--
-- Idioms of the book's case studies: a constant initialised by a call of a pure function of
-- constants (`time2real`), `time'pos(t) * 1.0e-15` (universal_integer times universal_real,
-- LRM 7.5.5, needs no conversion), and a spectral source quantity, which is zero outside a
-- frequency-domain analysis (here it only adds to `v`).

ENTITY tb_static_calls_and_sources IS
END ENTITY tb_static_calls_and_sources;

ARCHITECTURE test OF tb_static_calls_and_sources IS
  FUNCTION time2real (tt : TIME) RETURN REAL IS
  BEGIN
    RETURN time'POS(tt) * 1.0e-15;
  END time2real;
  CONSTANT t_ramp : TIME := 2 ms;
  CONSTANT r_ramp : REAL := time2real(t_ramp);
  QUANTITY ac_spec : REAL SPECTRUM 1.0, 0.0;
  QUANTITY v : REAL;
BEGIN
  v == 5.0 + ac_spec;

  check : PROCESS IS
  BEGIN
    ASSERT abs(r_ramp - 2.0e-3) < 1.0e-18
      REPORT "time2real(2 ms) = " & REAL'IMAGE(r_ramp) SEVERITY error;
    ASSERT abs(time2real(now + 3 ms) - 3.0e-3) < 1.0e-18
      REPORT "time2real(3 ms) at run time" SEVERITY error;
    WAIT FOR 1 ms;
    ASSERT v = 5.0 REPORT "a spectral source quantity must be zero in the time domain"
      SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
