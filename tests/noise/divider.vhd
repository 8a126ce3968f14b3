-- divider: a resistor divider from a 5 V supply, r1 over r2, with c across r2; each resistor
-- an instance of `noisy_resistor`, whose thermal noise (4kTR) is a noise voltage in series.
-- At the output the two add to 4kT (r1 || r2) / |1 + jw (r1 || r2) c|^2; over 0..inf, kT/C.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity noisy_resistor is
  generic (r : real; temp : real := 300.0);
  port (terminal p, n : electrical);
end entity;
architecture thermal of noisy_resistor is
  constant boltzmann : real := 1.380649e-23;
  quantity vn : real noise 4.0 * boltzmann * temp * r;
  quantity v across i through p to n;
begin
  v == r * i + vn;
end architecture;

library ieee;
use ieee.electrical_systems.all;
entity tb_divider is
  generic (r1 : real := 3.0e3; r2 : real := 1.0e3; c : real := 1.0e-9);
end entity;
architecture bench of tb_divider is
  terminal supply, mid : electrical;
  quantity vs across isup through supply to electrical_ref;
  quantity vout across ic through mid to electrical_ref;
begin
  vs == 5.0;
  top : entity work.noisy_resistor(thermal) generic map (r => r1) port map (supply, mid);
  bottom : entity work.noisy_resistor(thermal) generic map (r => r2) port map (mid, electrical_ref);
  ic == c * vout'dot;
end architecture;
