-- opamp_inverting: an inverting amplifier of gain -r2/r1 = -10 around an op-amp with finite
-- gain-bandwidth, a0 = 1e5 and one pole at fa = 10 Hz (1 MHz gain-bandwidth product):
--   vout = -a(s) vn, a(s) = a0 / (1 + s / (2 pi fa));  (vin - vn) / r1 = (vn - vout) / r2
--   H = vout / vin = -(r2 / r1) / (1 + (1 + r2 / r1) / a(s)),
-- flat at -10 (20 dB) up to about 91 kHz, where the loop runs out of gain.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_opamp_inverting is
  generic (r1 : real := 1.0e3; r2 : real := 10.0e3; a0 : real := 1.0e5; fa : real := 10.0);
end entity;
architecture bench of tb_opamp_inverting is
  terminal n_in, n_minus, n_out : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin across iin through n_in to electrical_ref;
  quantity v1 across i1 through n_in to n_minus;
  quantity v2 across i2 through n_minus to n_out;
  quantity vn across n_minus to electrical_ref;
  quantity vout across iout through n_out to electrical_ref;
begin
  vin == ac_in;
  v1 == r1 * i1;
  v2 == r2 * i2;
  -- The op-amp: no input current (vn is an across quantity only), an output source with
  -- one pole.
  vout + vout'dot / (math_2_pi * fa) == -a0 * vn;
end architecture;
