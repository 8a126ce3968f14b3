-- diode: exponential junction with series resistance.
--
-- Conservation (electrical): one branch from anode to cathode; the current i
-- that enters at the anode leaves at the cathode (KCL through the terminals).
--   v  = vj + rs*i
--   i  = is_sat*(exp(vj/(n*vt)) - 1)       for vj <= vj_lin
--        continued linearly (value and slope match) above vj_lin
-- Default: the reverse-battery diode of the module, about 0.7 V at the servo's
-- operating current of about 0.25 A (PAPER.md section 7, "reverse-battery diode").

library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;

entity diode is
  generic (
    is_sat : real := 1.2e-12;   -- [A] saturation current; 0.675 V junction drop at 0.25 A, so that
                                --     with rs the diode drops 0.70 V at the operating current (PAPER.md section 7)
    n      : real := 1.0;       -- [1] emission coefficient; ideal junction (no data to justify another)
    rs     : real := 0.1;       -- [Ohm] series resistance; bulk and leads of a 1 A rectifier diode
    vt     : real := 0.025865;  -- [V] thermal voltage k*T/q at 300.15 K (27 degC)
    vj_lin : real := 1.2        -- [V] junction voltage above which the exponential continues linearly;
                                --     far above any operating point, keeps Newton iterates finite
  );
  port (terminal anode, cathode : electrical);
end entity diode;

architecture behavioral of diode is
  constant nvt : real := n * vt;
  quantity v across i through anode to cathode;
  quantity vj : voltage;  -- junction voltage (the series resistance takes the rest)
begin
  v == vj + rs * i;

  -- Continuous in value and slope at vj_lin: no discontinuity, hence no break.
  if vj > vj_lin use
    i == is_sat * (exp(vj_lin / nvt) * (1.0 + (vj - vj_lin) / nvt) - 1.0);
  else
    i == is_sat * (exp(vj / nvt) - 1.0);
  end use;
end architecture behavioral;
