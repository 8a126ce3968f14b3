-- rlc_series: a series RLC driven by a spectral voltage source. The current peaks at
-- f0 = 1 / (2 pi sqrt(L C)) = 5032.92 Hz with quality factor Q = sqrt(L / C) / R = 3.162;
-- the capacitor voltage is H(jw) = 1 / (1 - w^2 L C + j w R C).
-- Analyse: vams ac rlc_series.vhd --from 100Hz --to 100kHz --probe vc --probe il
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_rlc_series is
  generic (r : real := 10.0; l : real := 1.0e-3; c : real := 1.0e-6);
end entity;
architecture bench of tb_rlc_series is
  terminal n_in, n_rl, n_c : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vs across is_src through n_in to electrical_ref;
  quantity vr across ir through n_in to n_rl;
  quantity vl across il through n_rl to n_c;
  quantity vc across icap through n_c to electrical_ref;
begin
  vs == 1.0 + ac_in;
  vr == r * ir;
  vl == l * il'dot;
  icap == c * vc'dot;
end architecture;
