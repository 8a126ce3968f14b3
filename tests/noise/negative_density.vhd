-- negative_density: a noise density that turns negative above 1 kHz; `vams noise` names
-- the source and the frequency.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_negative_density is
end entity;
architecture bench of tb_negative_density is
  terminal vout_n : electrical;
  quantity vn_bad : real noise 1.0e-16 * (1.0 - frequency / 1.0e3);
  quantity vr across ir through vout_n to electrical_ref;
  quantity vc across ic through vout_n to electrical_ref;
begin
  vr == 1.0e3 * ir + vn_bad;
  ic == 1.0e-9 * vc'dot;
end architecture;
