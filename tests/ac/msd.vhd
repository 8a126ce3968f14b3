-- msd: a mass-spring-damper (translational nature: displacement across, force through)
-- pushed by a spectral force. X / F = 1 / (k - m w^2 + j w d); resonance near
-- sqrt(k / m) / (2 pi) = 5.033 Hz.
-- Analyse: vams ac msd.vhd --from 0.1Hz --to 100Hz --probe x
-- vams: stop 1 ms
library ieee;
use ieee.mechanical_systems.all;
entity tb_msd is
  generic (m : real := 2.0; k : real := 2000.0; d : real := 4.0);
end entity;
architecture bench of tb_msd is
  terminal pos : translational;
  quantity f_ac : real spectrum 1.0, 0.0;
  quantity x across f_spring through pos to translational_ref;
  quantity x_damp across f_damp through pos to translational_ref;
  quantity x_mass across f_mass through pos to translational_ref;
  quantity f_push through translational_ref to pos;
begin
  f_spring == k * x;
  f_damp == d * x_damp'dot;
  f_mass == m * x_mass'dot'dot;
  f_push == 5.0 + f_ac;
end architecture;
