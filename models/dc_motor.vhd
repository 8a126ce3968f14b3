-- dc_motor: permanent-magnet DC motor (the paper's Table 1 and section 2).
--
-- Conservation: electrical branch p -> n (voltage v across, current i through);
-- rotational branch shaft -> rotational_v_ref (angular velocity w across,
-- torque t through, t being the torque the motor takes from the shaft node).
--   v = ke*w + r*i + l*di/dt
--   t = j*dw/dt + d*w - kt*i        i.e.  j*dw/dt = kt*i - d*w - t_load
-- SI units, so ke = kt.  Motor figures are not published (PAPER.md section 7):
-- the defaults are one consistent set for a 12 V leveling actuator, giving
-- about 0.23 A and 6100 rpm at 10.5 V under the servo's load.

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity dc_motor is
  generic (
    r  : real := 4.0;     -- [Ohm] armature resistance; a few ohms, inrush about 1.5 A through the bridge
    l  : real := 3.0e-3;  -- [H] armature inductance; a few mH, electrical time constant l/r = 0.75 ms
    kt : real := 0.015;   -- [N m/A] torque constant; equal to ke in SI units
    ke : real := 0.015;   -- [V s/rad] back-EMF constant; no-load speed about 6700 rpm at 11 V
    d  : real := 1.5e-6;  -- [N m s/rad] viscous damping; 0.96 mN m at 6100 rpm, so that with the motor's
                          --     constant friction the no-load current is about 0.1 A
    j  : real := 1.0e-6;  -- [kg m2] rotor inertia; the order of a 20 mm can-size motor
    i0 : real := 0.0;     -- [A] armature current at t = 0; at rest
    w0 : real := 0.0      -- [rad/s] shaft speed at t = 0; at rest
  );
  port (
    terminal p, n  : electrical;
    terminal shaft : rotational_v
  );
end entity dc_motor;

architecture behavioral of dc_motor is
  quantity v across i through p to n;
  quantity w across t through shaft to rotational_v_ref;
begin
  v == ke * w + r * i + l * i'dot;
  t == j * w'dot + d * w - kt * i;

  break i => i0, w => w0;  -- initial state (executed once, at the quiescent point)
end architecture behavioral;
