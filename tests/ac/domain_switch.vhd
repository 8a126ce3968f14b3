-- domain_switch: an equation that reads `domain`: in the frequency domain the stage has a gain
-- of 2 and a pole at 1 kHz, in the quiescent and time domains a gain of 1 (y follows u).
-- The small-signal model is the frequency domain's equations at the quiescent point.
-- vams: stop 1 ms
library ieee;
use ieee.math_real.all;
entity tb_domain_switch is end entity;
architecture bench of tb_domain_switch is
  quantity u_ac : real spectrum 1.0, 0.0;
  quantity u, y : real;
begin
  u == 1.0 + u_ac;
  if domain = frequency_domain use
    y + y'dot / (math_2_pi * 1.0e3) == 2.0 * u;
  else
    y == u;
  end use;
end architecture;
