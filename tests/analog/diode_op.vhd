-- The headlight's diode (models/diode.vhd, defaults) forward biased from 12 V through 47 Ohm.
library ieee;
use ieee.electrical_systems.all;

entity diode_op is
  generic (v : real := 12.0; r : real := 47.0);
end entity diode_op;

architecture test of diode_op is
  terminal a, k : electrical;
  quantity v_src across i_src through a to electrical_ref;
  quantity v_r across i_r through a to k;
begin
  v_src == v;
  v_r == r * i_r;
  d : entity work.diode(behavioral) port map (anode => k, cathode => electrical_ref);
end architecture test;
