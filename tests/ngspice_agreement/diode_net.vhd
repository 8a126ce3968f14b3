-- Reproduction from the analog-correctness issue, kept as a regression test (tests/it/ngspice_agreement.rs); the
-- lines below describe the behaviour before the fix.
-- R, C, series R-L and two diodes. Accepted points break the source equation: v1 is off amp*sin(2 pi f now) by 9x the amplitude at the default tolerance, 13 % at --reltol 1e-6; ngspice and --keep-unknowns (5e-4) do not.
-- Simulate: vams run diode_net.vhd --top tb_diode_net --stop 0.0003680100459236776 --reltol 1e-6; the SPICE twin is diode_net.cir.
-- vams: stop 0.0003680100459236776 sec
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
entity tb_diode_net is end entity;
architecture bench of tb_diode_net is
  terminal n1, n2, n3, n4, n5, n6, n7, n8, n9, n10 : electrical;
  terminal x0, x1, x13, x14 : electrical;
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
  quantity v9 across n9 to electrical_ref;
  quantity v10 across n10 to electrical_ref;
begin
  vs == 3.636264956104505 * sin(math_2_pi * 8151.9513753224455 * now);
  idc_q == -0.0010403504980834764;
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
  r0 : entity work.d_res(a) generic map (r => 688.3565083561646) port map (n1, x0);
  e0 : entity work.d_ind(a) generic map (l => 1.82831544590417e-05) port map (x0, n2);
  r1 : entity work.d_res(a) generic map (r => 27.956831548329735) port map (n2, x1);
  e1 : entity work.d_ind(a) generic map (l => 0.0009685805749197817) port map (x1, n3);
  e2 : entity work.d_dio(a) port map (n2, n4);
  e3 : entity work.d_res(a) generic map (r => 960.7130606124407) port map (n1, n5);
  e4 : entity work.d_cap(a) generic map (c => 4.426771614474075e-07) port map (n3, n6);
  e5 : entity work.d_dio(a) port map (electrical_ref, n7);
  e6 : entity work.d_cap(a) generic map (c => 3.3246276337007365e-08) port map (n5, n8);
  e7 : entity work.d_cap(a) generic map (c => 1.0102917242236485e-07) port map (n7, n9);
  e8 : entity work.d_cap(a) generic map (c => 4.20191715834303e-08) port map (n4, n10);
  e9 : entity work.d_res(a) generic map (r => 37.635632176036054) port map (electrical_ref, n1);
  e10 : entity work.d_res(a) generic map (r => 6656.768700947227) port map (n7, n9);
  e11 : entity work.d_res(a) generic map (r => 85.05656701384389) port map (n3, n8);
  e12 : entity work.d_res(a) generic map (r => 129.95652824251957) port map (electrical_ref, n9);
  r13 : entity work.d_res(a) generic map (r => 57.78705547586529) port map (n2, x13);
  e13 : entity work.d_ind(a) generic map (l => 3.45322920765008e-05) port map (x13, n7);
  r14 : entity work.d_res(a) generic map (r => 11.258535226464154) port map (n5, x14);
  e14 : entity work.d_ind(a) generic map (l => 1.253557736924144e-05) port map (x14, n2);
  e15 : entity work.d_cap(a) generic map (c => 1.3503626859615505e-09) port map (n5, n3);
  e16 : entity work.d_cap(a) generic map (c => 1.819227978117253e-07) port map (electrical_ref, n9);
  e17 : entity work.d_res(a) generic map (r => 66.27670504421673) port map (n3, n1);
  e18 : entity work.d_cap(a) generic map (c => 6.400345695258443e-08) port map (n8, n5);
  e19 : entity work.d_cap(a) generic map (c => 1.2732587638043722e-08) port map (n10, n6);
end architecture;
