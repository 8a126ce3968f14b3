-- 'slew of a quantity: a sine of amplitude 1 at 1 kHz (largest slope 2 pi 1000 = 6283/s)
-- limited to +-5000/s: the output follows where the sine is slow and moves at exactly
-- +-5000/s where it is fast.
library ieee;
use ieee.math_real.all;

entity slew_quantity is
end entity slew_quantity;

architecture test of slew_quantity is
  quantity x, y : real;
begin
  x == sin(2.0 * math_pi * 1.0e3 * now);
  y == x'slew(5000.0, -5000.0);
end architecture test;
