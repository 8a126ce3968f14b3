-- RC ladder of n sections charged from a 1 V source switched on at t = 0 (every capacitor
-- starts at 0 V). The line's total resistance and capacitance are fixed, so each section has
-- r_total / n and c_total / n and the waveform at `node(n)` tends to the distributed line's as
-- n grows. The sections are one for-generate over the terminal array `node`: section k joins
-- node(k - 1) to node(k) through its resistor and node(k) to ground through its capacitor.
library ieee;
use ieee.electrical_systems.all;

entity ladder_resistor is
  generic (r : real);
  port (terminal p, m : electrical);
end entity ladder_resistor;

architecture ideal of ladder_resistor is
  quantity v across i through p to m;
begin
  v == r * i;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity ladder_capacitor is
  generic (c : real);
  port (terminal p, m : electrical);
end entity ladder_capacitor;

architecture ideal of ladder_capacitor is
  quantity v across i through p to m;
begin
  i == c * v'dot;
  break v => 0.0;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity rc_ladder is
  generic (n : positive := 10; r_total : real := 1.0e3; c_total : real := 1.0e-6);
end entity rc_ladder;

architecture bench of rc_ladder is
  terminal node : electrical_vector(0 to n);
  quantity v_in across i_in through node(0) to electrical_ref;
  quantity v_out across node(n) to electrical_ref;
begin
  v_in == 1.0;
  ladder : for k in 1 to n generate
    res : entity work.ladder_resistor
      generic map (r => r_total / real(n))
      port map (p => node(k - 1), m => node(k));
    cap : entity work.ladder_capacitor
      generic map (c => c_total / real(n))
      port map (p => node(k), m => electrical_ref);
  end generate ladder;
end architecture bench;
