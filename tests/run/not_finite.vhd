-- vams: stop 2 sec
--
-- `r == sqrt(y)` with `y` negative after 1 s: the run must stop with the quantity, the time
-- and the equation, not write NaN to the waveforms and succeed.
library ieee;
use ieee.math_real.all;

entity not_finite is
end entity not_finite;

architecture a of not_finite is
  quantity y, r : real;
begin
  y == 1.0 - now;
  r == sqrt(y);
end architecture a;
