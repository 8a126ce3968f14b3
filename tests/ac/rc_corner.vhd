-- rc_corner: a unit test of a filter's frequency response, run by `vams test`: no stop
-- time, so only the assertions on the small-signal response are checked (each solved at its
-- frequency). The RC's corner is at 1 / (2 pi R C) = 1591.55 Hz: -3.0103 dB and -45 degrees.
-- vams: assert gain(vout, 1Hz) > 0.9999
-- vams: assert gain_db(vout, 1591.55Hz) > -3.02
-- vams: assert gain_db(vout, 1591.55Hz) < -3.00
-- vams: assert phase_deg(vout, 1591.55Hz) < -44.99
-- vams: assert gain_db(vout, 159.155kHz) < -39.9
library ieee;
use ieee.electrical_systems.all;
entity tb_rc_corner is
  generic (r : real := 1.0e3; c : real := 100.0e-9);
end entity;
architecture bench of tb_rc_corner is
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
