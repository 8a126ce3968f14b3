-- rc_lowpass: a first-order RC low-pass driven by a 1 V spectral source plus a 2 V bias.
-- |H| = 1 / sqrt(1 + (w R C)^2), phase -atan(w R C); the corner is at 1 / (2 pi R C) = 1591.55 Hz.
-- Analyse: vams ac rc_lowpass.vhd --top tb_rc_lowpass --from 1Hz --to 1MHz --probe vout
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_rc_lowpass is
  generic (r : real := 1.0e3; c : real := 100.0e-9);
end entity;
architecture bench of tb_rc_lowpass is
  terminal vin_n, vout_n : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin across iin through vin_n to electrical_ref;
  quantity vr across ir through vin_n to vout_n;
  quantity vout across ic through vout_n to electrical_ref;
begin
  vin == 2.0 + ac_in;
  vr == r * ir;
  ic == c * vout'dot;
end architecture;
