-- IEEE.MATH_REAL for vams: constants and elementary functions of type REAL (IEEE Std 1076.2).
--
-- Native subprograms: every subprogram of a vams stdlib package that is declared
-- without a body is implemented natively by the compiler and simulator. Nothing in
-- this package has a body, and there is no package body: all the functions below
-- are native, computed in IEEE double precision. Where an argument is outside a
-- function's domain (noted against each declaration) the native implementation
-- reports an assertion of severity ERROR and returns the value given in the note.
--
-- Note: REAL ** INTEGER is not declared here; it is the predefined "**" of
-- STD.STANDARD, and a second declaration would make X ** 2 ambiguous.

package math_real is

  --------------------------------------------------------------------------
  -- Constants (rounded to 21 significant digits)
  --------------------------------------------------------------------------
  constant math_e             : real := 2.71828182845904523536;   -- e
  constant math_1_over_e      : real := 0.367879441171442321596;  -- 1/e
  constant math_pi            : real := 3.14159265358979323846;   -- pi
  constant math_2_pi          : real := 6.28318530717958647693;   -- 2*pi
  constant math_1_over_pi     : real := 0.318309886183790671538;  -- 1/pi
  constant math_pi_over_2     : real := 1.57079632679489661923;   -- pi/2
  constant math_pi_over_3     : real := 1.04719755119659774615;   -- pi/3
  constant math_pi_over_4     : real := 0.785398163397448309616;  -- pi/4
  constant math_3_pi_over_2   : real := 4.71238898038468985769;   -- 3*pi/2
  constant math_log_of_2      : real := 0.693147180559945309417;  -- ln(2)
  constant math_log_of_10     : real := 2.30258509299404568402;   -- ln(10)
  constant math_log2_of_e     : real := 1.44269504088896340736;   -- log2(e)
  constant math_log10_of_e    : real := 0.434294481903251827651;  -- log10(e)
  constant math_sqrt_2        : real := 1.41421356237309504880;   -- sqrt(2)
  constant math_1_over_sqrt_2 : real := 0.707106781186547524401;  -- 1/sqrt(2)
  constant math_sqrt_pi       : real := 1.77245385090551602730;   -- sqrt(pi)
  constant math_deg_to_rad    : real := 0.0174532925199432957692; -- pi/180
  constant math_rad_to_deg    : real := 57.2957795130823208768;   -- 180/pi

  --------------------------------------------------------------------------
  -- Sign, rounding and comparison
  --------------------------------------------------------------------------
  -- 1.0 if x > 0.0, 0.0 if x = 0.0, -1.0 if x < 0.0.
  function sign (x : in real) return real;

  -- Smallest integral value not less than x.
  function ceil (x : in real) return real;

  -- Largest integral value not greater than x.
  function floor (x : in real) return real;

  -- Nearest integral value; halfway cases are rounded away from zero.
  function round (x : in real) return real;

  -- Integral part of x, rounded towards zero.
  function trunc (x : in real) return real;

  -- x - y * floor(x / y): the result has the sign of y and abs(result) < abs(y).
  -- y = 0.0 is an error (returns 0.0).
  function "mod" (x, y : in real) return real;

  -- The larger, and the smaller, of x and y.
  function realmax (x, y : in real) return real;
  function realmin (x, y : in real) return real;

  --------------------------------------------------------------------------
  -- Pseudo-random numbers
  --------------------------------------------------------------------------
  -- Returns in x a pseudo-random number uniformly distributed in the open
  -- interval (0.0, 1.0), and updates the seeds for the next call. This is
  -- L'Ecuyer's combined multiplicative linear congruential generator
  -- (Communications of the ACM 31(6), 1988), as in IEEE Std 1076.2:
  --   seed1 := 40014 * (seed1 mod 53668) - 12211 * (seed1 / 53668), plus 2147483563 if < 0
  --   seed2 := 40692 * (seed2 mod 52774) -  3791 * (seed2 / 52774), plus 2147483399 if < 0
  --   z := seed1 - seed2, plus 2147483562 if < 1;  x := real(z) * 4.656613e-10
  -- Seeds must satisfy 1 <= seed1 <= 2147483562 and 1 <= seed2 <= 2147483398
  -- (error otherwise: x := 0.0, seeds unchanged).
  procedure uniform (variable seed1, seed2 : inout positive; variable x : out real);

  --------------------------------------------------------------------------
  -- Roots, powers, exponentials and logarithms
  --------------------------------------------------------------------------
  -- Square root; x < 0.0 is an error (returns 0.0).
  function sqrt (x : in real) return real;

  -- Cube root, defined for all x.
  function cbrt (x : in real) return real;

  -- x raised to the power y. Errors: x < 0 (returns 0.0); x = 0 and y <= 0.0
  -- (returns 0.0). 0 ** y is 0.0 for y > 0.0; x ** 0.0 is 1.0 for x /= 0.
  function "**" (x : in integer; y : in real) return real;
  function "**" (x : in real;    y : in real) return real;

  -- e raised to the power x.
  function exp (x : in real) return real;

  -- Natural, base-2 and base-10 logarithms; x <= 0.0 is an error (returns REAL'LOW).
  function log   (x : in real) return real;
  function log2  (x : in real) return real;
  function log10 (x : in real) return real;

  -- Logarithm of x to the given base. Errors: x <= 0.0 (returns REAL'LOW);
  -- base <= 0.0 or base = 1.0 (returns 0.0).
  function log (x : in real; base : in real) return real;

  --------------------------------------------------------------------------
  -- Trigonometric functions (angles in radians)
  --------------------------------------------------------------------------
  function sin (x : in real) return real;
  function cos (x : in real) return real;
  function tan (x : in real) return real;

  -- Inverse sine and cosine; abs(x) > 1.0 is an error (returns 0.0).
  -- arcsin returns a value in [-pi/2, pi/2], arccos a value in [0, pi].
  function arcsin (x : in real) return real;
  function arccos (x : in real) return real;

  -- Inverse tangent of y, in (-pi/2, pi/2).
  function arctan (y : in real) return real;

  -- The angle of the point (x, y), in (-pi, pi]; x = 0.0 and y = 0.0 is an
  -- error (returns 0.0).
  function arctan (y : in real; x : in real) return real;

  --------------------------------------------------------------------------
  -- Hyperbolic functions
  --------------------------------------------------------------------------
  function sinh (x : in real) return real;
  function cosh (x : in real) return real;
  function tanh (x : in real) return real;

  function arcsinh (x : in real) return real;

  -- x < 1.0 is an error (returns 0.0).
  function arccosh (x : in real) return real;

  -- abs(x) >= 1.0 is an error (returns 0.0).
  function arctanh (x : in real) return real;

end package math_real;

-- The body holds what is written in VHDL; every subprogram declared above without a body
-- here is computed natively by vams.
package body math_real is

  procedure uniform (variable seed1, seed2 : inout positive; variable x : out real) is
    -- The products stay below 2**31 (40014 * 53668 < 2**31 - 1): no overflow.
    variable s1, s2, k, z : integer;
  begin
    if seed1 > 2147483562 or seed2 > 2147483398 then
      assert false
        report "uniform: seed1 must be in 1 to 2147483562 and seed2 in 1 to 2147483398"
        severity error;
      x := 0.0;
      return;
    end if;
    k := seed1 / 53668;
    s1 := 40014 * (seed1 - k * 53668) - k * 12211;
    if s1 < 0 then
      s1 := s1 + 2147483563;
    end if;
    k := seed2 / 52774;
    s2 := 40692 * (seed2 - k * 52774) - k * 3791;
    if s2 < 0 then
      s2 := s2 + 2147483399;
    end if;
    seed1 := s1;
    seed2 := s2;
    z := s1 - s2;
    if z < 1 then
      z := z + 2147483562;
    end if;
    x := real(z) * 4.656613e-10;
  end procedure uniform;

end package body math_real;
