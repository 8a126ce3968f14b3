-- diode_iv: a diode behind 1 kOhm from a source of level vs; `vams dc --sweep vs` traces
-- its I-V curve. The current solves id = is_sat (exp((vs - r id)/vt) - 1) + 1e-12 (vs - r id)
-- (tests/it/dc.rs checks it point by point, and against ngspice's `.dc` of the SPICE twin).
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_diode_iv is
  generic (vs_level : real := 0.0; r : real := 1.0e3; is_sat : real := 1.0e-14;
           vt : real := 0.025852);
end entity;
architecture bench of tb_diode_iv is
  terminal n_in, n_d : electrical;
  quantity vs across is_src through n_in to electrical_ref;
  quantity vr across ir through n_in to n_d;
  quantity vd across id through n_d to electrical_ref;
begin
  vs == vs_level;
  vr == r * ir;
  id == is_sat * (exp(vd / vt) - 1.0) + 1.0e-12 * vd;
end architecture;
