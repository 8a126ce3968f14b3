-- Diode chain of n stages driven by a 5 V, 10 kHz sine (issue 22's nonlinear benchmark):
-- stage k joins node(k - 1) to node(k) through 100 Ohm and a diode in series (the diode's
-- anode at the resistor), and node(k) to ground through 10 nF in parallel with 10 kOhm. Each
-- stage rectifies the one before it, so every diode switches once per period and the later
-- stages see a smaller, smoother wave. The diode is the SPICE default junction (IS 1e-14,
-- n 1, 300 K) with ngspice's GMIN of 1e-12 S across it, so that ngspice's `D` with a default
-- model is the same device.
-- vams: stop 200 us
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;

entity chain_diode is
  generic (is_sat : real := 1.0e-14; vt : real := 0.025852);
  port (terminal anode, cathode : electrical);
end entity chain_diode;

architecture shockley of chain_diode is
  quantity v across i through anode to cathode;
begin
  i == is_sat * (exp(v / vt) - 1.0) + 1.0e-12 * v;
end architecture shockley;

library ieee;
use ieee.electrical_systems.all;

entity chain_resistor is
  generic (r : real);
  port (terminal p, m : electrical);
end entity chain_resistor;

architecture ideal of chain_resistor is
  quantity v across i through p to m;
begin
  v == r * i;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity chain_capacitor is
  generic (c : real);
  port (terminal p, m : electrical);
end entity chain_capacitor;

architecture ideal of chain_capacitor is
  quantity v across i through p to m;
begin
  i == c * v'dot;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;

entity diode_chain is
  generic (n : positive := 100; amplitude : real := 5.0; frequency : real := 10.0e3);
end entity diode_chain;

architecture bench of diode_chain is
  terminal node : electrical_vector(0 to n);
  terminal mid : electrical_vector(1 to n);
  quantity v_in across i_in through node(0) to electrical_ref;
  quantity v_out across node(n) to electrical_ref;
  -- The first stages carry the wave (five volts pass through about seven diodes); n >= 3.
  quantity v_1 across node(1) to electrical_ref;
  quantity v_2 across node(2) to electrical_ref;
  quantity v_3 across node(3) to electrical_ref;
begin
  v_in == amplitude * sin(math_2_pi * frequency * now);
  stages : for k in 1 to n generate
    series : entity work.chain_resistor
      generic map (r => 100.0)
      port map (p => node(k - 1), m => mid(k));
    rectifier : entity work.chain_diode
      port map (anode => mid(k), cathode => node(k));
    hold : entity work.chain_capacitor
      generic map (c => 10.0e-9)
      port map (p => node(k), m => electrical_ref);
    load : entity work.chain_resistor
      generic map (r => 10.0e3)
      port map (p => node(k), m => electrical_ref);
  end generate stages;
end architecture bench;
