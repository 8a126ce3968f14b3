-- The headlight's dc_motor (models/dc_motor.vhd) on a 12 V source, free shaft: a linear
-- second-order system in (i, w) from rest.
library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity motor_step is
  generic (v : real := 12.0);
end entity motor_step;

architecture test of motor_step is
  terminal p : electrical;
  terminal shaft : rotational_v;
  quantity v_src across i_src through p to electrical_ref;
begin
  v_src == v;
  motor : entity work.dc_motor(behavioral)
    port map (p => p, n => electrical_ref, shaft => shaft);
end architecture test;
