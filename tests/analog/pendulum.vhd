-- A pendulum in Cartesian coordinates: a point mass on a rigid massless rod, the rod's force
-- `lam * (x, y)` keeping it on the circle `x**2 + y**2 == l**2`. Index 3: the constraint
-- reads only positions, whose second derivatives the forces set, so an integrator cannot
-- start from it as written (issue 15). vams differentiates the constraint twice (Pantelides)
-- and keeps the rest of the model as written, with dummy derivatives.
-- vams: stop 10 s
library ieee;
use ieee.math_real.all;

entity pendulum is
  generic (l : real := 1.0; m : real := 1.0; g : real := 9.81; theta0 : real := 0.3);
end entity pendulum;

architecture cartesian of pendulum is
  quantity x, y, u, v, lam : real;
begin
  x'dot == u;
  y'dot == v;
  m * u'dot == -lam * x;
  m * v'dot == -lam * y - m * g;
  x * x + y * y == l * l;
  break x => l * sin(theta0), y => -l * cos(theta0), u => 0.0, v => 0.0;
end architecture cartesian;
