-- RC ladder of n sections charged from a 1 V source switched on at t = 0 (every capacitor
-- starts at 0 V). The line's total resistance and capacitance are fixed, so each section has
-- r_total / n and c_total / n and the waveform at `output` tends to the distributed line's as
-- n grows. vams has no terminal arrays yet, so the chain is built by halving: `rc_chain` of n
-- sections is two chains of n / 2 joined at a fresh terminal (instance depth log2 n).
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

entity rc_chain is
  generic (n : positive; r, c : real);
  port (terminal a, b : electrical);
end entity rc_chain;

architecture halves of rc_chain is
begin
  one : if n = 1 generate
    res : entity work.ladder_resistor generic map (r => r) port map (p => a, m => b);
    cap : entity work.ladder_capacitor generic map (c => c) port map (p => b, m => electrical_ref);
  end generate one;
  two : if n > 1 generate
    terminal mid : electrical;
  begin
    left : entity work.rc_chain generic map (n => n / 2, r => r, c => c) port map (a => a, b => mid);
    right : entity work.rc_chain generic map (n => n - n / 2, r => r, c => c) port map (a => mid, b => b);
  end generate two;
end architecture halves;

library ieee;
use ieee.electrical_systems.all;

entity rc_ladder is
  generic (n : positive := 10; r_total : real := 1.0e3; c_total : real := 1.0e-6);
end entity rc_ladder;

architecture bench of rc_ladder is
  terminal input, output : electrical;
  quantity v_in across i_in through input to electrical_ref;
  quantity v_out across output to electrical_ref;
begin
  v_in == 1.0;
  chain : entity work.rc_chain
    generic map (n => n, r => r_total / real(n), c => c_total / real(n))
    port map (a => input, b => output);
end architecture bench;
