-- Reproduction from the analog-correctness issue, kept as a regression test (tests/it/ngspice_agreement.rs); the
-- lines below describe the behaviour before the fix.
-- `vams op` prints vs = 0.0256 V although the source equation gives 0 at t = 0, and KCL at n1 is off by about 6 uA; no warning. ngspice's .op satisfies both.
-- Simulate: vams run op_not_solution.vhd --top tb_op_not_solution --stop 3.252962352320038e-05 --reltol 1e-6; the SPICE twin is op_not_solution.cir.
-- vams: stop 3.252962352320038e-05 sec
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
entity tb_op_not_solution is end entity;
architecture bench of tb_op_not_solution is
  terminal n1, n2, n3, n4, n5, n6, n7 : electrical;
  terminal x0, x6 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n3;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
  quantity v5 across n5 to electrical_ref;
  quantity v6 across n6 to electrical_ref;
  quantity v7 across n7 to electrical_ref;
begin
  vs == 4.425834944465608 * sin(math_2_pi * 92223.63111151215 * now);
  idc_q == -0.0007453945290601856;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  leak5 : entity work.d_res(a) generic map (r => 1.0e8) port map (n5, electrical_ref);
  leak6 : entity work.d_res(a) generic map (r => 1.0e8) port map (n6, electrical_ref);
  leak7 : entity work.d_res(a) generic map (r => 1.0e8) port map (n7, electrical_ref);
  r0 : entity work.d_res(a) generic map (r => 86.72375933442136) port map (n1, x0);
  e0 : entity work.d_ind(a) generic map (l => 2.1858376085089103e-05) port map (x0, n2);
  e1 : entity work.d_res(a) generic map (r => 427.84117441014524) port map (n2, n3);
  e2 : entity work.d_res(a) generic map (r => 44.68784390768575) port map (electrical_ref, n4);
  e3 : entity work.d_dio(a) port map (n3, n5);
  e4 : entity work.d_res(a) generic map (r => 2462.867083006328) port map (n1, n6);
  e5 : entity work.d_cap(a) generic map (c => 2.3993726143486585e-09) port map (n5, n7);
  r6 : entity work.d_res(a) generic map (r => 26.975054975252736) port map (electrical_ref, x6);
  e6 : entity work.d_ind(a) generic map (l => 4.249806412492606e-05) port map (x6, n1);
end architecture;
