-- attributes: the frequency-domain meaning of 'delayed, 'ltf and 'integ, driven by a spectral
-- source whose magnitude reads FREQUENCY: u = (f / 1 kHz) e^(j pi/4);
-- y_delayed = e^(-jw 0.1 ms) u, y_ltf = u / (1 + 2 zeta s / w0 + s^2 / w0^2), y_integ = 1e3 u / (jw).
-- vams: stop 1 ms
library ieee;
use ieee.math_real.all;
entity tb_attributes is end entity;
architecture bench of tb_attributes is
  constant w0 : real := math_2_pi * 1.0e3;
  constant zeta : real := 0.3;
  constant num : real_vector := (0 => 1.0);
  constant den : real_vector := (1.0, 2.0 * zeta / w0, 1.0 / (w0 * w0));
  quantity u_ac : real spectrum frequency / 1.0e3, math_pi / 4.0;
  quantity u, y_delayed, y_ltf, y_integ : real;
begin
  u == u_ac;
  y_delayed == u'delayed(1.0e-4);
  y_ltf == u'ltf(num, den);
  y_integ == 1.0e3 * u'integ;
end architecture;
