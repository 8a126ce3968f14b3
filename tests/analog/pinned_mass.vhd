-- A mass whose position is prescribed, `x == a sin(w t)`, held by the force `f` that the model
-- solves for: index 3 with a source in time. Index reduction differentiates the position
-- twice, the source's time derivatives included (zero at the quiescent point, where time
-- stands still), so `f = m (g - a w**2 sin(w t))` and `v = a w cos(w t)` exactly; no state is
-- left (issue 15).
library ieee;
use ieee.math_real.all;

entity pinned_mass is
  generic (m : real := 0.5; g : real := 9.81; a : real := 0.1; w : real := 6.0);
end entity pinned_mass;

architecture test of pinned_mass is
  quantity x, v, f : real;
begin
  m * v'dot == f - m * g;
  x'dot == v;
  x == a * sin(w * now);
end architecture test;
