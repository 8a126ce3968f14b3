-- charged_loop: a current source charges n3 through its 100 MOhm leak to 46 kV behind a capacitor
-- (e2) that closes a loop with the source's capacitor (e4): elimination once wrote v(n1) as
-- e2.v - (e4.v - (-e2.v)), whose two 46 kV terms cancel only to 5e-12 V, more than the source's
-- tolerance, and Newton stopped at the first step (random circuit, seed 473838).
-- Simulate: vams run charged_loop.vhd --top tb_charged_loop --reltol 1e-6; the SPICE twin is charged_loop.cir.
-- vams: stop 6.567053952718207e-5 sec
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
entity tb_charged_loop is end entity;
architecture bench of tb_charged_loop is
  terminal n1, n2, n3 : electrical;
  terminal x0, x3 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity idc_q through electrical_ref to n3;
  quantity v1 across n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
begin
  vs == 1.2187944818285754 * sin(math_2_pi * 45682.584939906774 * now);
  idc_q == 0.0004644468599345215;
  leak1 : entity work.d_res(a) generic map (r => 1.0e8) port map (n1, electrical_ref);
  leak2 : entity work.d_res(a) generic map (r => 1.0e8) port map (n2, electrical_ref);
  leak3 : entity work.d_res(a) generic map (r => 1.0e8) port map (n3, electrical_ref);
  r0 : entity work.d_res(a) generic map (r => 33.63987916502495) port map (n1, x0);
  e0 : entity work.d_ind(a) generic map (l => 0.00021436687442090248) port map (x0, electrical_ref);
  e1 : entity work.d_dio(a) port map (electrical_ref, n2);
  e2 : entity work.d_cap(a) generic map (c => 7.527253286528026e-8) port map (n1, n3);
  r3 : entity work.d_res(a) generic map (r => 53.00451328644687) port map (electrical_ref, x3);
  e3 : entity work.d_ind(a) generic map (l => 1.452993362924148e-5) port map (x3, n2);
  e4 : entity work.d_cap(a) generic map (c => 2.0531656859865706e-7) port map (electrical_ref, n1);
end architecture;
