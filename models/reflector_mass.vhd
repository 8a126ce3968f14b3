-- reflector_mass: the reflector's mass referred to the gear output, i.e. to
-- the rack (mass_extrapolated in the paper's Table 1; translational inertia).
--
-- Conservation (translational): branch p -> translational_v_ref, velocity v
-- across, force f through.
--   f = mass_extrapolated * dv/dt

library ieee;
use ieee.mechanical_systems.all;

entity reflector_mass is
  generic (
    mass_extrapolated : real := 0.3  -- [kg] reflector with its carrier, linked 1:1 to the rack
  );
  port (terminal p : translational_v);
end entity reflector_mass;

architecture behavioral of reflector_mass is
  quantity v across f through p to translational_v_ref;
begin
  f == mass_extrapolated * v'dot;
end architecture behavioral;
