-- An RC charge (R = 1 kOhm, C = 1 uF, tau = 1 ms) built on a terminal array: the resistor has
-- one array port `t : electrical_vector(1 to 2)` connected whole to `rc : (0 to 1)` (elements
-- matched by position), the capacitor scalar ports connected to the indexed names rc(1) and
-- the reference. The quantity array w holds the capacitor voltage and its integral:
-- v_c = 1 - exp(-t/tau), w(2) = t - tau (1 - exp(-t/tau)).
library ieee;
use ieee.electrical_systems.all;

entity array_resistor is
  generic (r : real);
  port (terminal t : electrical_vector(1 to 2));
end entity array_resistor;

architecture ideal of array_resistor is
  quantity v across i through t(1) to t(2);
begin
  v == r * i;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity array_capacitor is
  generic (c : real);
  port (terminal p, m : electrical);
end entity array_capacitor;

architecture ideal of array_capacitor is
  quantity v across i through p to m;
begin
  i == c * v'dot;
  break v => 0.0;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity terminal_array_rc is
end entity terminal_array_rc;

architecture bench of terminal_array_rc is
  terminal rc : electrical_vector(0 to 1);
  quantity v_s across i_s through rc(0) to electrical_ref;
  quantity v_c across rc(rc'right) to electrical_ref;
  quantity w : real_vector(1 to 2);
begin
  v_s == 1.0;
  r : entity work.array_resistor generic map (r => 1.0e3) port map (t => rc);
  c : entity work.array_capacitor generic map (c => 1.0e-6) port map (p => rc(1), m => electrical_ref);
  w(1) == v_c;
  w(2)'dot == w(1);
  break w(2) => 0.0;
end architecture bench;
