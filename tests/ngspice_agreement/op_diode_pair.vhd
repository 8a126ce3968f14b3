-- op_diode_pair: A current source driving a loop of two diodes (d3, d4) through an inductor and resistors:
-- the operating point once stopped on the same false rounding floor as op_diode_leak, with v2,
-- v3 and v6 29 mV low (0.228 V for 0.257 V), 2.5 % of the swing (random circuit, seed 950).
-- Simulate: vams run op_diode_pair.vhd --top tb_op_diode_pair --reltol 1e-6; the SPICE twin is op_diode_pair.cir.
-- vams: stop 2.5000077027022646e-4 sec
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
entity tb_op_diode_pair is end entity;
architecture bench of tb_op_diode_pair is
  terminal n1, n2, n3, n4, n5, n6 : electrical;
  terminal x0, x2, x11 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n4;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
  quantity v5 across n5 to electrical_ref;
  quantity v6 across n6 to electrical_ref;
begin
  vs == 0.5753804545806925 * sin(math_2_pi * 11999.963027143047 * now);
  idc_q == 0.0015709649889801356;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  leak5 : entity work.d_res(a) generic map (r => 1.0e8) port map (n5, electrical_ref);
  leak6 : entity work.d_res(a) generic map (r => 1.0e8) port map (n6, electrical_ref);
  r0 : entity work.d_res(a) generic map (r => 12.875644352357908) port map (n1, x0);
  e0 : entity work.d_ind(a) generic map (l => 3.6505326680052425e-5) port map (x0, electrical_ref);
  e1 : entity work.d_cap(a) generic map (c => 1.475438813009765e-7) port map (electrical_ref, n2);
  r2 : entity work.d_res(a) generic map (r => 56.79522191875425) port map (n3, x2);
  e2 : entity work.d_ind(a) generic map (l => 0.00010028330235475636) port map (x2, n2);
  e3 : entity work.d_dio(a) port map (n4, n3);
  e4 : entity work.d_dio(a) port map (n2, n5);
  e5 : entity work.d_res(a) generic map (r => 21.470753446531923) port map (n2, n6);
  e6 : entity work.d_res(a) generic map (r => 43.51369009910027) port map (n4, n5);
  e7 : entity work.d_cap(a) generic map (c => 9.706562693327615e-9) port map (n2, n3);
  e8 : entity work.d_cap(a) generic map (c => 1.9913351600477645e-9) port map (n1, electrical_ref);
  e9 : entity work.d_cap(a) generic map (c => 1.0569257605746437e-8) port map (n2, n6);
  e10 : entity work.d_res(a) generic map (r => 386.4745333247694) port map (electrical_ref, n4);
  r11 : entity work.d_res(a) generic map (r => 19.258443846295993) port map (electrical_ref, x11);
  e11 : entity work.d_ind(a) generic map (l => 0.00018502173942908293) port map (x11, n1);
end architecture;
