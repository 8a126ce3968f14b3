-- IEEE.MATH_COMPLEX for vams: complex numbers in Cartesian and polar form and the
-- elementary functions of them (the interface of IEEE Std 1076.2), written for this project
-- in plain VHDL on top of ieee.math_real.
--
-- Conventions: a polar argument is the principal value, in (-pi, pi]; the logarithms and
-- square roots return their principal branch. Dividing by zero, or taking the logarithm of
-- zero, is reported with severity error and returns the largest real in magnitude (as the
-- standard's reference bodies do) rather than an infinity.

library ieee;
use ieee.math_real.all;

package math_complex is

  type complex is record
    re : real;  -- real part
    im : real;  -- imaginary part
  end record complex;

  subtype positive_real is real range 0.0 to real'high;
  subtype principal_value is real range -math_pi to math_pi;

  type complex_polar is record
    mag : positive_real;    -- magnitude
    arg : principal_value;  -- angle in radians
  end record complex_polar;

  constant math_cbase_1 : complex := (re => 1.0, im => 0.0);
  constant math_cbase_j : complex := (re => 0.0, im => 1.0);
  constant math_czero   : complex := (re => 0.0, im => 0.0);

  -- Equality of polar numbers: equal magnitudes and, for a non-zero magnitude, equal
  -- principal arguments (every zero is equal to every other).
  function "="  (l : in complex_polar; r : in complex_polar) return boolean;
  function "/=" (l : in complex_polar; r : in complex_polar) return boolean;

  -- x + j y
  function cmplx (x : in real; y : in real := 0.0) return complex;
  -- The angle x reduced to (-pi, pi].
  function get_principal_value (x : in real) return principal_value;
  function complex_to_polar (z : in complex) return complex_polar;
  function polar_to_complex (z : in complex_polar) return complex;

  function "abs" (z : in complex) return positive_real;
  function "abs" (z : in complex_polar) return positive_real;
  function arg (z : in complex) return principal_value;
  function arg (z : in complex_polar) return principal_value;

  function "-" (z : in complex) return complex;
  function "-" (z : in complex_polar) return complex_polar;
  function conj (z : in complex) return complex;
  function conj (z : in complex_polar) return complex_polar;

  function sqrt (z : in complex) return complex;
  function sqrt (z : in complex_polar) return complex_polar;
  function exp (z : in complex) return complex;
  function exp (z : in complex_polar) return complex_polar;
  function log (z : in complex) return complex;
  function log2 (z : in complex) return complex;
  function log10 (z : in complex) return complex;
  function log (z : in complex_polar) return complex_polar;
  function log2 (z : in complex_polar) return complex_polar;
  function log10 (z : in complex_polar) return complex_polar;
  function log (z : in complex; base : in real) return complex;
  function log (z : in complex_polar; base : in real) return complex_polar;

  function sin (z : in complex) return complex;
  function sin (z : in complex_polar) return complex_polar;
  function cos (z : in complex) return complex;
  function cos (z : in complex_polar) return complex_polar;
  function sinh (z : in complex) return complex;
  function sinh (z : in complex_polar) return complex_polar;
  function cosh (z : in complex) return complex;
  function cosh (z : in complex_polar) return complex_polar;

  function "+" (l : in complex; r : in complex) return complex;
  function "+" (l : in real; r : in complex) return complex;
  function "+" (l : in complex; r : in real) return complex;
  function "+" (l : in complex_polar; r : in complex_polar) return complex_polar;
  function "+" (l : in real; r : in complex_polar) return complex_polar;
  function "+" (l : in complex_polar; r : in real) return complex_polar;

  function "-" (l : in complex; r : in complex) return complex;
  function "-" (l : in real; r : in complex) return complex;
  function "-" (l : in complex; r : in real) return complex;
  function "-" (l : in complex_polar; r : in complex_polar) return complex_polar;
  function "-" (l : in real; r : in complex_polar) return complex_polar;
  function "-" (l : in complex_polar; r : in real) return complex_polar;

  function "*" (l : in complex; r : in complex) return complex;
  function "*" (l : in real; r : in complex) return complex;
  function "*" (l : in complex; r : in real) return complex;
  function "*" (l : in complex_polar; r : in complex_polar) return complex_polar;
  function "*" (l : in real; r : in complex_polar) return complex_polar;
  function "*" (l : in complex_polar; r : in real) return complex_polar;

  function "/" (l : in complex; r : in complex) return complex;
  function "/" (l : in real; r : in complex) return complex;
  function "/" (l : in complex; r : in real) return complex;
  function "/" (l : in complex_polar; r : in complex_polar) return complex_polar;
  function "/" (l : in real; r : in complex_polar) return complex_polar;
  function "/" (l : in complex_polar; r : in real) return complex_polar;

end package math_complex;

package body math_complex is

  -- The real that stands for an infinite result (1076.2: the largest real, signed).
  constant huge : real := real'high;

  function "=" (l : in complex_polar; r : in complex_polar) return boolean is
  begin
    if l.mag = 0.0 and r.mag = 0.0 then
      return true;
    end if;
    return l.mag = r.mag and l.arg = r.arg;
  end function "=";

  function "/=" (l : in complex_polar; r : in complex_polar) return boolean is
  begin
    return not (l = r);
  end function "/=";

  function cmplx (x : in real; y : in real := 0.0) return complex is
  begin
    return (re => x, im => y);
  end function cmplx;

  function get_principal_value (x : in real) return principal_value is
    variable a : real := x;
  begin
    if a > -math_pi and a <= math_pi then
      return a;
    end if;
    -- Into [0, 2 pi), then (-pi, pi].
    a := a - math_2_pi * floor(a / math_2_pi);
    if a > math_pi then
      a := a - math_2_pi;
    end if;
    if a < -math_pi then
      a := -math_pi;
    end if;
    return a;
  end function get_principal_value;

  function complex_to_polar (z : in complex) return complex_polar is
  begin
    if z.re = 0.0 and z.im = 0.0 then
      return (mag => 0.0, arg => 0.0);
    end if;
    return (mag => sqrt(z.re * z.re + z.im * z.im), arg => arctan(z.im, z.re));
  end function complex_to_polar;

  function polar_to_complex (z : in complex_polar) return complex is
  begin
    return (re => z.mag * cos(z.arg), im => z.mag * sin(z.arg));
  end function polar_to_complex;

  function "abs" (z : in complex) return positive_real is
    variable a : real := abs z.re;
    variable b : real := abs z.im;
    variable t : real;
  begin
    -- sqrt(a**2 + b**2) without overflowing for large parts.
    if a < b then
      t := a;
      a := b;
      b := t;
    end if;
    if a = 0.0 then
      return 0.0;
    end if;
    t := b / a;
    return a * sqrt(1.0 + t * t);
  end function "abs";

  function "abs" (z : in complex_polar) return positive_real is
  begin
    return z.mag;
  end function "abs";

  function arg (z : in complex) return principal_value is
  begin
    if z.re = 0.0 and z.im = 0.0 then
      return 0.0;
    end if;
    return arctan(z.im, z.re);
  end function arg;

  function arg (z : in complex_polar) return principal_value is
  begin
    return z.arg;
  end function arg;

  function "-" (z : in complex) return complex is
  begin
    return (re => -z.re, im => -z.im);
  end function "-";

  function "-" (z : in complex_polar) return complex_polar is
  begin
    if z.mag = 0.0 then
      return z;
    end if;
    return (mag => z.mag, arg => get_principal_value(z.arg + math_pi));
  end function "-";

  function conj (z : in complex) return complex is
  begin
    return (re => z.re, im => -z.im);
  end function conj;

  function conj (z : in complex_polar) return complex_polar is
  begin
    if z.arg = math_pi then
      return z;
    end if;
    return (mag => z.mag, arg => -z.arg);
  end function conj;

  function sqrt (z : in complex) return complex is
    variable m : real := abs z;
    variable u, v : real;
  begin
    if m = 0.0 then
      return math_czero;
    end if;
    -- The principal root: non-negative real part, imaginary part of z's sign.
    u := sqrt(0.5 * (m + abs z.re));
    v := z.im / (2.0 * u);
    if z.re >= 0.0 then
      return (re => u, im => v);
    elsif z.im >= 0.0 then
      return (re => abs v, im => u);
    else
      return (re => abs v, im => -u);
    end if;
  end function sqrt;

  function sqrt (z : in complex_polar) return complex_polar is
  begin
    return (mag => sqrt(z.mag), arg => 0.5 * z.arg);
  end function sqrt;

  function exp (z : in complex) return complex is
    variable m : real := exp(z.re);
  begin
    return (re => m * cos(z.im), im => m * sin(z.im));
  end function exp;

  function exp (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(exp(polar_to_complex(z)));
  end function exp;

  function log (z : in complex) return complex is
  begin
    if z.re = 0.0 and z.im = 0.0 then
      report "MATH_COMPLEX.LOG: the logarithm of zero" severity error;
      return (re => -huge, im => 0.0);
    end if;
    return (re => log(abs z), im => arctan(z.im, z.re));
  end function log;

  function log2 (z : in complex) return complex is
    variable l : complex := log(z);
  begin
    return (re => l.re * math_log2_of_e, im => l.im * math_log2_of_e);
  end function log2;

  function log10 (z : in complex) return complex is
    variable l : complex := log(z);
  begin
    return (re => l.re * math_log10_of_e, im => l.im * math_log10_of_e);
  end function log10;

  function log (z : in complex; base : in real) return complex is
    variable l : complex := log(z);
    variable lb : real;
  begin
    if base <= 0.0 or base = 1.0 then
      report "MATH_COMPLEX.LOG: the base must be positive and not 1" severity error;
      return (re => -huge, im => 0.0);
    end if;
    lb := log(base);
    return (re => l.re / lb, im => l.im / lb);
  end function log;

  function log (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(log(polar_to_complex(z)));
  end function log;

  function log2 (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(log2(polar_to_complex(z)));
  end function log2;

  function log10 (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(log10(polar_to_complex(z)));
  end function log10;

  function log (z : in complex_polar; base : in real) return complex_polar is
  begin
    return complex_to_polar(log(polar_to_complex(z), base));
  end function log;

  -- sin(x + jy) = sin x cosh y + j cos x sinh y, and so on.
  function sin (z : in complex) return complex is
  begin
    return (re => sin(z.re) * cosh(z.im), im => cos(z.re) * sinh(z.im));
  end function sin;

  function sin (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(sin(polar_to_complex(z)));
  end function sin;

  function cos (z : in complex) return complex is
  begin
    return (re => cos(z.re) * cosh(z.im), im => -sin(z.re) * sinh(z.im));
  end function cos;

  function cos (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(cos(polar_to_complex(z)));
  end function cos;

  function sinh (z : in complex) return complex is
  begin
    return (re => sinh(z.re) * cos(z.im), im => cosh(z.re) * sin(z.im));
  end function sinh;

  function sinh (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(sinh(polar_to_complex(z)));
  end function sinh;

  function cosh (z : in complex) return complex is
  begin
    return (re => cosh(z.re) * cos(z.im), im => sinh(z.re) * sin(z.im));
  end function cosh;

  function cosh (z : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(cosh(polar_to_complex(z)));
  end function cosh;

  -- Arithmetic. Polar operands are converted to Cartesian form for sums and differences;
  -- products and quotients work on magnitudes and arguments.

  function "+" (l : in complex; r : in complex) return complex is
  begin
    return (re => l.re + r.re, im => l.im + r.im);
  end function "+";

  function "+" (l : in real; r : in complex) return complex is
  begin
    return (re => l + r.re, im => r.im);
  end function "+";

  function "+" (l : in complex; r : in real) return complex is
  begin
    return (re => l.re + r, im => l.im);
  end function "+";

  function "+" (l : in complex_polar; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) + polar_to_complex(r));
  end function "+";

  function "+" (l : in real; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(l + polar_to_complex(r));
  end function "+";

  function "+" (l : in complex_polar; r : in real) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) + r);
  end function "+";

  function "-" (l : in complex; r : in complex) return complex is
  begin
    return (re => l.re - r.re, im => l.im - r.im);
  end function "-";

  function "-" (l : in real; r : in complex) return complex is
  begin
    return (re => l - r.re, im => -r.im);
  end function "-";

  function "-" (l : in complex; r : in real) return complex is
  begin
    return (re => l.re - r, im => l.im);
  end function "-";

  function "-" (l : in complex_polar; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) - polar_to_complex(r));
  end function "-";

  function "-" (l : in real; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(l - polar_to_complex(r));
  end function "-";

  function "-" (l : in complex_polar; r : in real) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) - r);
  end function "-";

  function "*" (l : in complex; r : in complex) return complex is
  begin
    return (re => l.re * r.re - l.im * r.im, im => l.re * r.im + l.im * r.re);
  end function "*";

  function "*" (l : in real; r : in complex) return complex is
  begin
    return (re => l * r.re, im => l * r.im);
  end function "*";

  function "*" (l : in complex; r : in real) return complex is
  begin
    return (re => l.re * r, im => l.im * r);
  end function "*";

  function "*" (l : in complex_polar; r : in complex_polar) return complex_polar is
  begin
    if l.mag = 0.0 or r.mag = 0.0 then
      return (mag => 0.0, arg => 0.0);
    end if;
    return (mag => l.mag * r.mag, arg => get_principal_value(l.arg + r.arg));
  end function "*";

  function "*" (l : in real; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(l * polar_to_complex(r));
  end function "*";

  function "*" (l : in complex_polar; r : in real) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) * r);
  end function "*";

  function "/" (l : in complex; r : in complex) return complex is
    variable d, ratio : real;
  begin
    if r.re = 0.0 and r.im = 0.0 then
      report "MATH_COMPLEX.""/"": division by zero" severity error;
      return (re => huge, im => huge);
    end if;
    -- Smith's algorithm: scale by the larger part of the divisor, so that no product
    -- overflows where the quotient does not.
    if abs r.re >= abs r.im then
      ratio := r.im / r.re;
      d := r.re + r.im * ratio;
      return (re => (l.re + l.im * ratio) / d, im => (l.im - l.re * ratio) / d);
    else
      ratio := r.re / r.im;
      d := r.re * ratio + r.im;
      return (re => (l.re * ratio + l.im) / d, im => (l.im * ratio - l.re) / d);
    end if;
  end function "/";

  function "/" (l : in real; r : in complex) return complex is
  begin
    return cmplx(l) / r;
  end function "/";

  function "/" (l : in complex; r : in real) return complex is
  begin
    if r = 0.0 then
      report "MATH_COMPLEX.""/"": division by zero" severity error;
      return (re => huge, im => huge);
    end if;
    return (re => l.re / r, im => l.im / r);
  end function "/";

  function "/" (l : in complex_polar; r : in complex_polar) return complex_polar is
  begin
    if r.mag = 0.0 then
      report "MATH_COMPLEX.""/"": division by zero" severity error;
      return (mag => huge, arg => 0.0);
    end if;
    if l.mag = 0.0 then
      return (mag => 0.0, arg => 0.0);
    end if;
    return (mag => l.mag / r.mag, arg => get_principal_value(l.arg - r.arg));
  end function "/";

  function "/" (l : in real; r : in complex_polar) return complex_polar is
  begin
    return complex_to_polar(l / polar_to_complex(r));
  end function "/";

  function "/" (l : in complex_polar; r : in real) return complex_polar is
  begin
    return complex_to_polar(polar_to_complex(l) / r);
  end function "/";

end package body math_complex;
