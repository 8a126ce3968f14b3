-- diode_stage: a diode biased at about 4.3 mA through 1 kOhm from 5 V, with 10 nF across it;
-- the spectral source rides on the bias. The small-signal response is that of the diode's
-- conductance at the quiescent point, g = Is/vt exp(v/vt) + 1e-12, in parallel with C:
-- H = (1/R) / (1/R + g + jwC). The SPICE twin is in tests/it/ac.rs (300 K, Is 1e-14, GMIN 1e-12).
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_diode_stage is
  generic (r : real := 1.0e3; c : real := 10.0e-9; is_sat : real := 1.0e-14;
           vt : real := 0.025852);
end entity;
architecture bench of tb_diode_stage is
  terminal n_in, n_d : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vs across is_src through n_in to electrical_ref;
  quantity vr across ir through n_in to n_d;
  quantity vd across id through n_d to electrical_ref;
  quantity vc across icap through n_d to electrical_ref;
begin
  vs == 5.0 + ac_in;
  vr == r * ir;
  id == is_sat * (exp(vd / vt) - 1.0) + 1.0e-12 * vd;
  icap == c * vc'dot;
end architecture;
