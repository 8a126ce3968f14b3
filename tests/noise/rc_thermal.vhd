-- rc_thermal: the thermal noise of a resistor (4kTR, a noise voltage in series with it) into
-- a capacitor. Output density sqrt(4kTR) / |1 + jwRC|; over 0..inf the output noise power is
-- kT/C. A 1 V spectral source drives the input for `vams ac` (zero in the noise analysis).
-- Analyse: vams noise rc_thermal.vhd --probe vout --from 1Hz --to 1GHz
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_rc_thermal is
  generic (r : real := 1.0e3; c : real := 1.0e-9; temp : real := 300.0);
end entity;
architecture bench of tb_rc_thermal is
  constant boltzmann : real := 1.380649e-23;
  terminal vin_n, vout_n : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vn_r : real noise 4.0 * boltzmann * temp * r;
  quantity vin across iin through vin_n to electrical_ref;
  quantity vr across ir through vin_n to vout_n;
  quantity vout across ic through vout_n to electrical_ref;
begin
  vin == 1.0 + ac_in;
  vr == r * ir + vn_r;
  ic == c * vout'dot;
end architecture;
