-- RC low pass charged from a 1 V source switched on at t = 0: v_c(t) = 1 - exp(-t / (r c)).
library ieee;
use ieee.electrical_systems.all;

entity rc_charge is
  generic (r : real := 1.0e3; c : real := 1.0e-6);
end entity rc_charge;

architecture test of rc_charge is
  terminal n_in, n_out : electrical;
  quantity v_in across i_in through n_in to electrical_ref;
  quantity v_r across i_r through n_in to n_out;
  quantity v_c across i_c through n_out to electrical_ref;
begin
  v_in == 1.0;
  v_r == r * i_r;
  i_c == c * v_c'dot;
  break v_c => 0.0;
end architecture test;
