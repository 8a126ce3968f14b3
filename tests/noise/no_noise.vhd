-- no_noise: an RC with a spectral source and no noise source; `vams noise` refuses it.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_no_noise is
end entity;
architecture bench of tb_no_noise is
  terminal vin_n, vout_n : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin across iin through vin_n to electrical_ref;
  quantity vr across ir through vin_n to vout_n;
  quantity vout across ic through vout_n to electrical_ref;
begin
  vin == ac_in;
  vr == 1.0e3 * ir;
  ic == 1.0e-9 * vout'dot;
end architecture;
