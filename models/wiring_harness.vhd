-- wiring_harness: the two lines between the IC outputs and the motor
-- connectors, each a series resistance and inductance.
--
-- Conservation (electrical): two branches, a1 -> b1 and a2 -> b2; the current of
-- each line enters at a and leaves at b.
--   v1 = r_line*i1 + l_line*di1/dt,   v2 = r_line*i2 + l_line*di2/dt
-- Defaults: 2.5 m of 0.5 mm2 wire per line.

library ieee;
use ieee.electrical_systems.all;

entity wiring_harness is
  generic (
    r_line : real := 0.1;     -- [Ohm] 2.5 m x 39 mOhm/m, 0.5 mm2 class 5 conductor (IEC 60228, PAPER.md section 7)
    l_line : real := 3.75e-6  -- [H] 2.5 m x 1.5 uH/m straight wire (Grover, PAPER.md section 7)
  );
  port (terminal a1, b1, a2, b2 : electrical);
end entity wiring_harness;

architecture behavioral of wiring_harness is
  quantity v1 across i1 through a1 to b1;
  quantity v2 across i2 through a2 to b2;
begin
  v1 == r_line * i1 + l_line * i1'dot;
  v2 == r_line * i2 + l_line * i2'dot;
end architecture behavioral;
