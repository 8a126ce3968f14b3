-- spring: linear translational spring, the elasticity of the mechanism (the
-- reflector's return spring acting on the rack; the paper's Table 1).
--
-- Conservation (translational): branch p -> n, relative velocity v across,
-- force f through.
--   dx/dt = v,   f = ks * x       (x: elongation from the rest length)

library ieee;
use ieee.mechanical_systems.all;

entity spring is
  generic (
    ks : real := 5000.0;  -- [N/m] 5 N/mm: 20 N at mid-stroke, 0.04 mN m at the motor, held by the friction 60 times over
    x0 : real := 0.0      -- [m] elongation at t = 0; relaxed at the start position
  );
  port (terminal p, n : translational_v);
end entity spring;

architecture behavioral of spring is
  quantity v across f through p to n;
  quantity x : displacement;
begin
  x'dot == v;
  f == ks * x;

  break x => x0;  -- initial elongation
end architecture behavioral;
