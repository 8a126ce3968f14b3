-- The Cartesian pendulum of `pendulum.vhd` with a delayed copy of its horizontal position.
-- Released at 2 rad it swings past the horizontal, where vams chooses other states and
-- rebuilds its system (issue 15); the delay line's history must survive that.
library ieee;
use ieee.math_real.all;

entity pendulum_delayed is
  generic (l : real := 1.0; m : real := 1.0; g : real := 9.81; theta0 : real := 2.0;
           lag : real := 0.05);
end entity pendulum_delayed;

architecture cartesian of pendulum_delayed is
  quantity x, y, u, v, lam, x_late : real;
begin
  x'dot == u;
  y'dot == v;
  m * u'dot == -lam * x;
  m * v'dot == -lam * y - m * g;
  x * x + y * y == l * l;
  x_late == x'delayed(lag);
  break x => l * sin(theta0), y => -l * cos(theta0), u => 0.0, v => 0.0;
end architecture cartesian;
