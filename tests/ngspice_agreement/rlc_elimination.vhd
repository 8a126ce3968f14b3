-- Reproduction from the analog-correctness issue, kept as a regression test (tests/it/ngspice_agreement.rs); the
-- lines below describe the behaviour before the fix.
-- A linear RLC network. Default run and --keep-unknowns differ by 0.086 V (10 % of the 0.88 V swing) on v2 and v4 at any --reltol; --keep-unknowns agrees with ngspice to 7e-6 V.
-- Simulate: vams run rlc_elimination.vhd --top tb_rlc_elimination --stop 0.0005973208538396804 --reltol 1e-6; the SPICE twin is rlc_elimination.cir.
-- vams: stop 0.0005973208538396804 sec
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
architecture a of d_dio is quantity v across i through p to n; begin i == is_sat * (exp(v / vt) - 1.0); end architecture;

library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_rlc_elimination is end entity;
architecture bench of tb_rlc_elimination is
  terminal n1, n2, n3, n4, n5, n6, n7, n8, n9 : electrical;
  terminal x0, x11 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n3;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
  quantity v5 across n5 to electrical_ref;
  quantity v6 across n6 to electrical_ref;
  quantity v7 across n7 to electrical_ref;
  quantity v8 across n8 to electrical_ref;
  quantity v9 across n9 to electrical_ref;
begin
  vs == 0.7888485921734735 * sin(math_2_pi * 5022.4263571504125 * now);
  idc_q == -0.0015011484297328122;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  leak5 : entity work.d_res(a) generic map (r => 1.0e8) port map (n5, electrical_ref);
  leak6 : entity work.d_res(a) generic map (r => 1.0e8) port map (n6, electrical_ref);
  leak7 : entity work.d_res(a) generic map (r => 1.0e8) port map (n7, electrical_ref);
  leak8 : entity work.d_res(a) generic map (r => 1.0e8) port map (n8, electrical_ref);
  leak9 : entity work.d_res(a) generic map (r => 1.0e8) port map (n9, electrical_ref);
  r0 : entity work.d_res(a) generic map (r => 52.16205142051774) port map (electrical_ref, x0);
  e0 : entity work.d_ind(a) generic map (l => 3.489927083750194e-05) port map (x0, n2);
  e1 : entity work.d_cap(a) generic map (c => 2.0509373521024863e-09) port map (electrical_ref, n3);
  e2 : entity work.d_cap(a) generic map (c => 1.9709580247836647e-09) port map (n2, n4);
  e3 : entity work.d_res(a) generic map (r => 36.99893145173163) port map (n3, n5);
  e4 : entity work.d_cap(a) generic map (c => 1.6259588506153786e-09) port map (electrical_ref, n6);
  e5 : entity work.d_cap(a) generic map (c => 2.4056904873131868e-09) port map (n6, n7);
  e6 : entity work.d_res(a) generic map (r => 32.825866981649654) port map (n4, n8);
  e7 : entity work.d_res(a) generic map (r => 187.34889366227813) port map (electrical_ref, n9);
  e8 : entity work.d_res(a) generic map (r => 303.6739502268803) port map (electrical_ref, n1);
  e9 : entity work.d_cap(a) generic map (c => 1.488770880418787e-09) port map (n9, n6);
  e10 : entity work.d_res(a) generic map (r => 13.906548872023551) port map (n1, n9);
  r11 : entity work.d_res(a) generic map (r => 82.12369801000051) port map (n9, x11);
  e11 : entity work.d_ind(a) generic map (l => 0.0007699784666545944) port map (x11, n3);
  e12 : entity work.d_cap(a) generic map (c => 4.559081386474811e-09) port map (n8, n5);
end architecture;
