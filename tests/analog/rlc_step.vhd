-- Series RLC driven by a 1 V step at t = 0 (capacitor discharged, no current): underdamped,
-- v_c(t) = 1 - exp(-a t) (cos(wd t) + a / wd sin(wd t)), a = r / (2 l), wd = sqrt(1/(l c) - a^2).
library ieee;
use ieee.electrical_systems.all;

entity rlc_step is
  generic (r : real := 10.0; l : real := 1.0e-3; c : real := 1.0e-6);
end entity rlc_step;

architecture test of rlc_step is
  terminal n_in, n_mid, n_out : electrical;
  quantity v_in across i_in through n_in to electrical_ref;
  quantity v_r across i_r through n_in to n_mid;
  quantity v_l across i_l through n_mid to n_out;
  quantity v_c across i_c through n_out to electrical_ref;
begin
  v_in == 1.0;
  v_r == r * i_r;
  v_l == l * i_l'dot;
  i_c == c * v_c'dot;
  break v_c => 0.0, i_l => 0.0;
end architecture test;
