-- potentiometer: feedback potentiometer on the rack, position to voltage
-- (factor k, the paper's Table 1), on its own supply.
--
-- Conservation: translational branch slider -> translational_v_ref (velocity
-- vel across, force f through) and electrical branch wiper -> electrical_ref
-- (voltage vw across, current iw through).
--   f = 0               the sensor takes no force from the mechanism
--   dx/dt = vel
--   vw = k * x          an ideal source: the pot's own regulated supply, independent of
--                       the IC supply; the IC input draws no current
-- k * stroke must stay within the pot's supply (5 V over 8 mm with the defaults).

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity potentiometer is
  generic (
    k  : real := 625.0;  -- [V/m] 5 V supply over an 8 mm stroke; 0.8 V/s at the running speed
    x0 : real := 0.0     -- [m] slider position at t = 0; the tracking run starts at 0
  );
  port (
    terminal slider : translational_v;
    terminal wiper  : electrical
  );
end entity potentiometer;

architecture behavioral of potentiometer is
  quantity vel across f through slider to translational_v_ref;
  quantity vw across iw through wiper to electrical_ref;
  quantity x : displacement;
begin
  f == 0.0;
  x'dot == vel;
  vw == k * x;

  break x => x0;  -- initial position
end architecture behavioral;
