-- Reproduction from the analog-correctness issue, kept as a regression test (tests/it/ngspice_agreement.rs); the
-- lines below describe the behaviour before the fix.
-- A voltage source feeding a capacitive divider (a loop of a source and capacitors, which every
-- SPICE simulates): vams stops at t = 0 with "time step fell to 1.7e-18".
-- Simulate: vams run cv_divider.vhd --top tb_cv --stop 3ms
-- vams: stop 3 ms
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
use ieee.math_real.all;
entity tb_cv is end entity;
architecture bench of tb_cv is
  terminal n1, n2 : electrical;
  quantity vs across is_src through n1 to electrical_ref;
  quantity v2 across n2 to electrical_ref;
begin
  vs == 2.0 * sin(math_2_pi * 1000.0 * now);
  c2 : entity work.d_cap(a) generic map (c => 2.0e-8) port map (n1, n2);
  c3 : entity work.d_cap(a) generic map (c => 6.0e-8) port map (n2, electrical_ref);
  r4 : entity work.d_res(a) generic map (r => 12.0) port map (n1, n2);
end architecture;
