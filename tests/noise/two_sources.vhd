-- two_sources: two uncorrelated noise sources at one node, a resistor's thermal noise
-- voltage (4kTR in series with r) and a current noise (i_psd A^2/Hz into the node), loaded
-- by c. Z = r / (1 + jwrc); output PSD 4kTR / |1 + jwrc|^2 + i_psd |Z|^2: powers add.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_two_sources is
  generic (r : real := 10.0e3; c : real := 1.0e-9; temp : real := 300.0;
           i_psd : real := 4.0e-24);
end entity;
architecture bench of tb_two_sources is
  constant boltzmann : real := 1.380649e-23;
  terminal vout_n : electrical;
  quantity vn_r : real noise 4.0 * boltzmann * temp * r;
  quantity in_x : real noise i_psd;
  quantity vr across ir through vout_n to electrical_ref;
  quantity vc across ic through vout_n to electrical_ref;
  quantity vx across ix through vout_n to electrical_ref;
begin
  vr == r * ir + vn_r;
  ic == c * vc'dot;
  ix == in_x;
end architecture;
