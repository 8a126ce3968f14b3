-- A resistor between two internal terminals that nothing ties to the reference.
library ieee;
use ieee.electrical_systems.all;

entity resistor is
  generic (r : real := 1.0e3);
  port (terminal p, n : electrical);
end entity resistor;

architecture a of resistor is
  quantity v across i through p to n;
begin
  v == r * i;
end architecture a;

library ieee;
use ieee.electrical_systems.all;

entity floating_terminal is
end entity floating_terminal;

architecture a of floating_terminal is
  terminal a, b : electrical;
begin
  r1 : entity work.resistor port map (p => a, n => b);
end architecture a;
