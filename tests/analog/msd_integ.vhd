-- Mass-spring-damper written with 'integ: m v' = f - c v - k x, x = v'integ, a force step f
-- at t = 0 from rest. Underdamped: x(t) = (f/k) (1 - exp(-a t) (cos(wd t) + a/wd sin(wd t))),
-- a = c / (2 m), wd = sqrt(k/m - a^2).
entity msd_integ is
  generic (m : real := 0.5; c : real := 0.8; k : real := 200.0; f : real := 2.0);
end entity msd_integ;

architecture test of msd_integ is
  quantity v : real;
  quantity x : real;
begin
  m * v'dot == f - c * v - k * v'integ;
  x == v'integ;
  break v => 0.0;
end architecture test;
