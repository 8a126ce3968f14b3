-- 'delayed of a sine: y(t) = sin(w (t - d)) once t > d, and the quiescent sin(0) = 0 before.
library ieee;
use ieee.math_real.all;

entity delayed_sine is
  generic (f : real := 1.0e3; d : real := 0.25e-3);
end entity delayed_sine;

architecture test of delayed_sine is
  quantity x, y : real;
begin
  x == sin(2.0 * math_pi * f * now);
  y == x'delayed(d);
end architecture test;
