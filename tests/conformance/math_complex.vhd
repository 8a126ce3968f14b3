-- vams: stop 1 ns
--
-- ieee.math_complex (IEEE 1076.2): Cartesian and polar arithmetic, conversions, the
-- elementary functions, against values worked out by hand, and the frequency response of an
-- RC low pass at its corner, H = 1 / (1 + j w RC): |H| = 1/sqrt(2), arg H = -pi/4.

LIBRARY ieee;
USE ieee.math_real.ALL;
USE ieee.math_complex.ALL;

ENTITY tb_math_complex IS
END ENTITY tb_math_complex;

ARCHITECTURE test OF tb_math_complex IS
  FUNCTION near (a, b : complex) RETURN boolean IS
  BEGIN
    RETURN abs(a - b) < 1.0e-12;
  END FUNCTION near;
  FUNCTION near (a, b : real) RETURN boolean IS
  BEGIN
    RETURN abs(a - b) < 1.0e-12;
  END FUNCTION near;
BEGIN
  check : PROCESS IS
    CONSTANT r : real := 1.0e3;
    CONSTANT c : real := 1.0e-6;
    VARIABLE z, w, h : complex;
    VARIABLE p, q : complex_polar;
  BEGIN
    z := cmplx(3.0, 4.0);
    w := cmplx(1.0, -2.0);
    ASSERT abs(z) = 5.0 REPORT "abs" SEVERITY failure;
    ASSERT near(z + w, cmplx(4.0, 2.0)) AND near(z - w, cmplx(2.0, 6.0))
      REPORT "sum, difference" SEVERITY failure;
    ASSERT near(z * w, cmplx(11.0, -2.0)) REPORT "product" SEVERITY failure;
    ASSERT near(z / w, cmplx(-1.0, 2.0)) REPORT "quotient" SEVERITY failure;
    ASSERT near(2.0 * z, cmplx(6.0, 8.0)) AND near(z / 2.0, cmplx(1.5, 2.0))
      AND near(1.0 + z, cmplx(4.0, 4.0)) REPORT "mixed real operands" SEVERITY failure;
    ASSERT near(conj(z), cmplx(3.0, -4.0)) AND near(-z, cmplx(-3.0, -4.0))
      REPORT "conj, negation" SEVERITY failure;
    ASSERT near(sqrt(cmplx(-4.0, 0.0)), cmplx(0.0, 2.0))
      AND near(sqrt(cmplx(0.0, 2.0)), cmplx(1.0, 1.0)) REPORT "sqrt" SEVERITY failure;
    ASSERT near(exp(cmplx(0.0, math_pi)), cmplx(-1.0, 0.0)) REPORT "exp" SEVERITY failure;
    ASSERT near(log(cmplx(-1.0, 0.0)), cmplx(0.0, math_pi)) REPORT "log" SEVERITY failure;
    ASSERT near(log10(cmplx(100.0, 0.0)), cmplx(2.0, 0.0)) REPORT "log10" SEVERITY failure;
    ASSERT near(sin(cmplx(0.0, 1.0)), cmplx(0.0, sinh(1.0)))
      AND near(cos(cmplx(0.0, 1.0)), cmplx(cosh(1.0), 0.0)) REPORT "sin, cos" SEVERITY failure;
    ASSERT near(math_cbase_j * math_cbase_j, -math_cbase_1) REPORT "j * j" SEVERITY failure;

    p := complex_to_polar(cmplx(0.0, -2.0));
    ASSERT near(p.mag, 2.0) AND near(p.arg, -math_pi_over_2) REPORT "to polar" SEVERITY failure;
    q := p * p;
    ASSERT near(q.mag, 4.0) AND near(q.arg, math_pi) REPORT "polar product" SEVERITY failure;
    ASSERT near(polar_to_complex(q), cmplx(-4.0, 0.0)) REPORT "to complex" SEVERITY failure;
    ASSERT near(get_principal_value(3.0 * math_pi), math_pi)
      AND near(get_principal_value(-1.5 * math_pi), math_pi_over_2)
      REPORT "principal value" SEVERITY failure;
    ASSERT complex_polar'(mag => 0.0, arg => 1.0) = complex_polar'(mag => 0.0, arg => -1.0)
      REPORT "zeros are equal" SEVERITY failure;

    h := 1.0 / (1.0 + cmplx(0.0, 1.0 / (r * c)) * (r * c));
    ASSERT near(abs(h), math_1_over_sqrt_2) AND near(arg(h), -math_pi_over_4)
      REPORT "RC corner: |H| = " & real'image(abs(h)) SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
