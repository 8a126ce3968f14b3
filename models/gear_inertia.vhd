-- gear_inertia: moment of inertia of the gear train, referred to the motor
-- shaft (a separate rotational contributor, the paper's Table 1).
--
-- Conservation (rotational): branch shaft -> rotational_v_ref, angular velocity
-- w across, torque t through.
--   t = jg * dw/dt

library ieee;
use ieee.mechanical_systems.all;

entity gear_inertia is
  generic (
    jg : real := 0.3e-6  -- [kg m2] worm and first wheel referred to the motor shaft; about a third of the rotor's
  );
  port (terminal shaft : rotational_v);
end entity gear_inertia;

architecture behavioral of gear_inertia is
  quantity w across t through shaft to rotational_v_ref;
begin
  t == jg * w'dot;
end architecture behavioral;
