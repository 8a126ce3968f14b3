-- Two inertias joined by a rigid gear (`w1 == ratio * w2`, `t2 == ratio * t1`): an index-2
-- system, started from rest by a break at time 0 on both speeds. A constant torque on the
-- motor side, viscous friction on the load: the load speed rises as
-- w2(t) = (ratio / d2) (1 - exp(-t / tau)), tau = (j1 ratio**2 + j2) / d2 (issue 15).
entity rigid_gear is
  generic (j1 : real := 0.01; j2 : real := 0.5; d2 : real := 0.2; ratio : real := 3.0);
end entity rigid_gear;

architecture test of rigid_gear is
  quantity w1, w2, t1, t2 : real;
begin
  j1 * w1'dot == 1.0 - t1;
  j2 * w2'dot == t2 - d2 * w2;
  w1 == ratio * w2;
  t2 == ratio * t1;
  break w1 => 0.0, w2 => 0.0;
end architecture test;
