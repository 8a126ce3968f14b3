-- op_diode_leak: A diode (e7) whose only load is two 100 MOhm leaks, one behind an inductor: a few nA, so
-- Newton walks down the junction's exponential by about vt per full step from the first guess.
-- Those steps do not contract, and the old rounding-floor test took that for convergence: the
-- current balances were within their tolerances (a 12 Ohm branch makes a loose one) while v8
-- and v9 sat 19 mV below the operating point (0.097 V for 0.116 V), 1.1 % of the swing from
-- the first step on (random circuit, seed 605). The floor now also needs a residual that no
-- longer falls.
-- Simulate: vams run op_diode_leak.vhd --top tb_op_diode_leak --reltol 1e-6; the SPICE twin is op_diode_leak.cir.
-- vams: stop 3.399357615254123e-4 sec
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
entity tb_op_diode_leak is end entity;
architecture bench of tb_op_diode_leak is
  terminal n1, n2, n3, n4, n5, n6, n7, n8, n9, n10 : electrical;
  terminal x2, x8 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n7;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
  quantity v5 across n5 to electrical_ref;
  quantity v6 across n6 to electrical_ref;
  quantity v7 across n7 to electrical_ref;
  quantity v8 across n8 to electrical_ref;
  quantity v9 across n9 to electrical_ref;
  quantity v10 across n10 to electrical_ref;
begin
  vs == 1.8527477638318173 * sin(math_2_pi * 8825.196815239256 * now);
  idc_q == 0.0017294905750558666;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  leak5 : entity work.d_res(a) generic map (r => 1.0e8) port map (n5, electrical_ref);
  leak6 : entity work.d_res(a) generic map (r => 1.0e8) port map (n6, electrical_ref);
  leak7 : entity work.d_res(a) generic map (r => 1.0e8) port map (n7, electrical_ref);
  leak8 : entity work.d_res(a) generic map (r => 1.0e8) port map (n8, electrical_ref);
  leak9 : entity work.d_res(a) generic map (r => 1.0e8) port map (n9, electrical_ref);
  leak10 : entity work.d_res(a) generic map (r => 1.0e8) port map (n10, electrical_ref);
  e0 : entity work.d_dio(a) port map (electrical_ref, n1);
  e1 : entity work.d_cap(a) generic map (c => 2.7923436349677116e-8) port map (n2, n1);
  r2 : entity work.d_res(a) generic map (r => 12.251325935198981) port map (n3, x2);
  e2 : entity work.d_ind(a) generic map (l => 0.0007023285359504343) port map (x2, n1);
  e3 : entity work.d_res(a) generic map (r => 2160.085610995052) port map (n4, n2);
  e4 : entity work.d_cap(a) generic map (c => 2.6504741121058395e-9) port map (n4, n5);
  e5 : entity work.d_cap(a) generic map (c => 1.7458509192569082e-7) port map (n6, electrical_ref);
  e6 : entity work.d_res(a) generic map (r => 1844.3697794712505) port map (n2, n7);
  e7 : entity work.d_dio(a) port map (n7, n8);
  r8 : entity work.d_res(a) generic map (r => 21.063737082076138) port map (n8, x8);
  e8 : entity work.d_ind(a) generic map (l => 0.0009745397665420593) port map (x8, n9);
  e9 : entity work.d_cap(a) generic map (c => 2.8086095962328144e-7) port map (n2, n10);
  e10 : entity work.d_dio(a) port map (electrical_ref, n3);
  e11 : entity work.d_res(a) generic map (r => 248.60395710910973) port map (n3, n7);
  e12 : entity work.d_res(a) generic map (r => 5569.758703383342) port map (n1, n2);
  e13 : entity work.d_res(a) generic map (r => 827.1200749455271) port map (n3, electrical_ref);
end architecture;
