-- An ideal LC tank started with the capacitor at 1 V: energy c v^2 / 2 + l i^2 / 2 is
-- conserved exactly by the equations; the integrator may only lose a little of it.
library ieee;
use ieee.electrical_systems.all;

entity lc_tank is
  generic (l : real := 1.0e-3; c : real := 1.0e-6);
end entity lc_tank;

architecture test of lc_tank is
  terminal n : electrical;
  quantity v_l across i_l through n to electrical_ref;
  quantity v_c across i_c through n to electrical_ref;
begin
  v_l == l * i_l'dot;
  i_c == c * v_c'dot;
  break v_c => 1.0, i_l => 0.0;
end architecture test;
