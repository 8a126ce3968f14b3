-- diode_across_source: A diode straight across the sine source (e7, conducting up to 2.2 V forward: about 1e22 A, a
-- conductance of 1e36 S beside the source row's 1). Partial pivoting on the raw Newton matrix
-- took the diode's row for the source node's column and then found the source current's column
-- empty: "singular Jacobian" at t = 2.4e-4 s (random circuit, seed 140). Rows are now
-- equilibrated before the factorisation.
-- Simulate: vams run diode_across_source.vhd --top tb_diode_across_source --reltol 1e-6; the SPICE twin is diode_across_source.cir.
-- vams: stop 1.128028797552487e-3 sec
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
entity tb_diode_across_source is end entity;
architecture bench of tb_diode_across_source is
  terminal n1, n2, n3, n4 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n2;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
  quantity v4 across n4 to electrical_ref;
begin
  vs == 2.1907036040942507 * sin(math_2_pi * 2659.506571560209 * now);
  idc_q == -9.92744638886629e-5;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  leak4 : entity work.d_res(a) generic map (r => 1.0e8) port map (n4, electrical_ref);
  e0 : entity work.d_res(a) generic map (r => 4556.5280990079655) port map (electrical_ref, n1);
  e1 : entity work.d_cap(a) generic map (c => 1.157460296175084e-9) port map (n1, n2);
  e2 : entity work.d_res(a) generic map (r => 4235.3714213921285) port map (n1, n3);
  e3 : entity work.d_res(a) generic map (r => 4952.071474549494) port map (n4, n1);
  e4 : entity work.d_res(a) generic map (r => 5638.895470029005) port map (n3, electrical_ref);
  e5 : entity work.d_res(a) generic map (r => 2488.791041848329) port map (n2, n3);
  e6 : entity work.d_res(a) generic map (r => 29.911004158041646) port map (n2, n3);
  e7 : entity work.d_dio(a) port map (electrical_ref, n1);
end architecture;
