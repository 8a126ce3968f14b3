-- rack_pinion_gear: reduction gear and pinion driving a rack, rotation to
-- translation, ideal and power conserving (the paper's Table 1).
--
-- Conservation: rotational branch pinion -> rotational_v_ref (w across,
-- torque tau through) and translational branch rack -> translational_v_ref
-- (velocity v across, force f through).  With ratio = radius_p / gear_ratio:
--   v   = ratio * w
--   tau = -ratio * f          so that  tau*w + f*v = 0  (no loss, no storage)
-- Losses are lumped in constant_friction, inertia in gear_inertia.

library ieee;
use ieee.mechanical_systems.all;

entity rack_pinion_gear is
  generic (
    gear_ratio : real := 60.0;   -- [1] motor turns per pinion turn; a worm stage of 1:60
    radius_p   : real := 1.2e-4  -- [m] pinion radius; the equivalent radius lead/(2*pi) of a 0.75 mm-lead
                                 --     spindle, so the rack moves 1.3 mm/s at 6100 rpm
  );
  port (
    terminal pinion : rotational_v;
    terminal rack   : translational_v
  );
end entity rack_pinion_gear;

architecture behavioral of rack_pinion_gear is
  constant ratio : real := radius_p / gear_ratio;  -- [m/rad] rack travel per motor radian
  quantity w across tau through pinion to rotational_v_ref;
  quantity v across f through rack to translational_v_ref;
begin
  v == ratio * w;
  tau == -ratio * f;
end architecture behavioral;
