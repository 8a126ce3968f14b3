-- source_capacitor_current: A capacitor straight across the sine source (e0): the source current is C times the
-- derivative of the source's waveform, which BDF computes to first order only, so its local
-- error test drove the step to 1e-19 s at t = 3.8e-5 s (random circuit, seed 204; 1.9 million
-- steps with --keep-unknowns at reltol 1e-6). Such higher-index algebraic unknowns now sit out
-- the error test, as in IDA and SPICE.
-- Simulate: vams run source_capacitor_current.vhd --top tb_source_capacitor_current --reltol 1e-6; the SPICE twin is source_capacitor_current.cir.
-- vams: stop 9.040550626315031e-5 sec
library ieee;
use ieee.electrical_systems.all;
entity d_res is generic (r : real); port (terminal p, n : electrical); end entity;
architecture a of d_res is quantity v across i through p to n; begin v == i * r; end architecture;
library ieee;
use ieee.electrical_systems.all;
entity d_cap is generic (c : real); port (terminal p, n : electrical); end entity;
architecture a of d_cap is quantity v across i through p to n; begin i == c * v'dot; end architecture;
library ieee;
use ieee.electrical_systems.all;
entity d_ind is generic (l : real); port (terminal p, n : electrical); end entity;
architecture a of d_ind is quantity v across i through p to n; begin v == l * i'dot; end architecture;
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity d_dio is generic (is_sat : real := 1.0e-14; vt : real := 0.025852); port (terminal p, n : electrical); end entity;
architecture a of d_dio is quantity v across i through p to n; begin i == is_sat * (exp(v / vt) - 1.0) + 1.0e-12 * v; end architecture;

library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_source_capacitor_current is end entity;
architecture bench of tb_source_capacitor_current is
  terminal n1, n2, n3, n4, n5, n6, n7, n8 : electrical;
  terminal x1, x3, x6 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n8;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
  quantity v5 across n5 to electrical_ref;
  quantity v6 across n6 to electrical_ref;
  quantity v7 across n7 to electrical_ref;
  quantity v8 across n8 to electrical_ref;
begin
  vs == 2.6225299969404188 * sin(math_2_pi * 33183.819481831866 * now);
  idc_q == -0.001296819069273155;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  leak5 : entity work.d_res(a) generic map (r => 1.0e8) port map (n5, electrical_ref);
  leak6 : entity work.d_res(a) generic map (r => 1.0e8) port map (n6, electrical_ref);
  leak7 : entity work.d_res(a) generic map (r => 1.0e8) port map (n7, electrical_ref);
  leak8 : entity work.d_res(a) generic map (r => 1.0e8) port map (n8, electrical_ref);
  e0 : entity work.d_cap(a) generic map (c => 2.3487899900031083e-7) port map (electrical_ref, n1);
  r1 : entity work.d_res(a) generic map (r => 73.09954056903256) port map (n1, x1);
  e1 : entity work.d_ind(a) generic map (l => 6.67890447749938e-5) port map (x1, n2);
  e2 : entity work.d_res(a) generic map (r => 2254.194300920914) port map (n3, n1);
  r3 : entity work.d_res(a) generic map (r => 27.026371878113203) port map (n4, x3);
  e3 : entity work.d_ind(a) generic map (l => 0.00016772907463853207) port map (x3, n2);
  e4 : entity work.d_cap(a) generic map (c => 6.054067015724248e-9) port map (n2, n5);
  e5 : entity work.d_cap(a) generic map (c => 1.1046111081649383e-8) port map (n1, n6);
  r6 : entity work.d_res(a) generic map (r => 98.89136546704064) port map (n1, x6);
  e6 : entity work.d_ind(a) generic map (l => 6.22168974365873e-5) port map (x6, n7);
  e7 : entity work.d_res(a) generic map (r => 4403.0272710651725) port map (n8, n2);
  e8 : entity work.d_dio(a) port map (n6, n4);
  e9 : entity work.d_cap(a) generic map (c => 2.072295273960636e-7) port map (n1, n2);
  e10 : entity work.d_cap(a) generic map (c => 4.482601975695312e-7) port map (n2, n5);
  e11 : entity work.d_cap(a) generic map (c => 5.641491327628787e-9) port map (n7, n8);
  e12 : entity work.d_cap(a) generic map (c => 2.9025812987354e-7) port map (n1, n5);
  e13 : entity work.d_cap(a) generic map (c => 6.990551137048266e-7) port map (n3, n4);
  e14 : entity work.d_cap(a) generic map (c => 6.55046445602705e-8) port map (n5, n3);
end architecture;
