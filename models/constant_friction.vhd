-- constant_friction: speed-independent friction Tcst = tcst_motor + tcst_system,
-- opposing motion (the paper's Table 1, applied at the motor output).
--
-- Conservation (rotational): branch shaft -> rotational_v_ref, angular velocity w
-- across, friction torque t through (taken from the shaft node).
--   t = (tcst_motor + tcst_system) * tanh(w / w_s)
-- Stiction, honestly: the sign function is smoothed over the stated velocity
-- scale w_s.  Below w_s the law is a steep viscous one (slope Tcst/w_s), so the
-- shaft is held "at rest" by a creep: a static load T < Tcst turns it at
-- w = w_s*atanh(T/Tcst).  For the spring load of the servo at rest (T/Tcst
-- about 0.01) that is about 1e-3 rad/s, a feedback drift of about 2e-6 V/s.
-- No state, no event, hence no chatter.  A smaller w_s holds tighter but makes
-- the equation stiffer for Newton; a stick/slip model with break would hold
-- exactly at the price of events.

library ieee;
use ieee.mechanical_systems.all;
use ieee.math_real.all;

entity constant_friction is
  generic (
    tcst_motor  : real := 0.5e-3;  -- [N m] motor brushes and bearings, what the coast-down capture
                                   --     extracts (PAPER.md section 3 d); about 0.03 A of motor current
    tcst_system : real := 2.0e-3;  -- [N m] worm gear and spindle friction referred to the motor shaft; sets
                                   --     the running current (0.23 A, hence about 10.5 V at the motor) and
                                   --     helps the brake stop the reflector 0.024 V past the deadband edge
    w_s         : real := 0.1      -- [rad/s] velocity scale of the smoothing; about 1/6000 of the running speed
  );
  port (terminal shaft : rotational_v);
end entity constant_friction;

architecture behavioral of constant_friction is
  constant tcst : real := tcst_motor + tcst_system;
  quantity w across t through shaft to rotational_v_ref;
begin
  t == tcst * tanh(w / w_s);
end architecture behavioral;
