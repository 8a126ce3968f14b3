-- A sine current source driving two inductors in series into a resistor: every node but the
-- resistor's is a cut set of the source and inductors, so the inductor currents are the source's
-- waveform and their voltages its derivative (index 2; SPICE's modified nodal analysis runs it).
-- The closed form: i = a sin(w t), v(n3) = r i, v(n1) - v(n3) = (l1 + l2) a w cos(w t).
-- Simulate: vams run cut_set.vhd --top tb_cut_set --stop 2ms
-- vams: stop 2 ms
library ieee;
use ieee.electrical_systems.all;
entity d_res is generic (r : real); port (terminal p, n : electrical); end entity;
architecture a of d_res is quantity v across i through p to n; begin v == i * r; end architecture;
library ieee;
use ieee.electrical_systems.all;
entity d_ind is generic (l : real); port (terminal p, n : electrical); end entity;
architecture a of d_ind is quantity v across i through p to n; begin v == l * i'dot; end architecture;
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
entity tb_cut_set is end entity;
architecture bench of tb_cut_set is
  terminal n1, n2, n3 : electrical;
  quantity vs across is_src through electrical_ref to n1;
  quantity v1 across n1 to electrical_ref;
  quantity v3 across n3 to electrical_ref;
begin
  is_src == 1.0e-3 * sin(math_2_pi * 1000.0 * now);
  l1 : entity work.d_ind(a) generic map (l => 1.0e-3) port map (n1, n2);
  l2 : entity work.d_ind(a) generic map (l => 3.0e-3) port map (n2, n3);
  r1 : entity work.d_res(a) generic map (r => 100.0) port map (n3, electrical_ref);
end architecture;
