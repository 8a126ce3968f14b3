-- flicker: a 1/f noise voltage (PSD kf / f, V^2/Hz) in series with the resistor of an RC
-- low-pass. Output PSD kf / f / |1 + jwRC|^2; with the corner far above the band (a small
-- c) the band's noise power is kf ln(f2 / f1).
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_flicker is
  generic (r : real := 1.0e3; c : real := 1.0e-9; kf : real := 1.0e-12);
end entity;
architecture bench of tb_flicker is
  terminal vin_n, vout_n : electrical;
  quantity vn_f : real noise kf / frequency;
  quantity vin across iin through vin_n to electrical_ref;
  quantity vr across ir through vin_n to vout_n;
  quantity vout across ic through vout_n to electrical_ref;
begin
  vin == 0.0;
  vr == r * ir + vn_f;
  ic == c * vout'dot;
end architecture;
