-- lead: a lead network, r1 parallel to c1 in series, r2 to ground. From the source to vout,
--   H(s) = r2 (1 + s r1 c1) / (r1 + r2 + s r1 r2 c1):
-- a zero at -1 / (r1 c1) = -100 /s and a pole at -(r1 + r2) / (r1 r2 c1) = -1100 /s
-- (`vams poles tests/ac/lead.vhd --input ac_in --output vout`).
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_lead is
  generic (r1 : real := 10.0e3; c1 : real := 1.0e-6; r2 : real := 1.0e3);
end entity;
architecture bench of tb_lead is
  terminal n_in, n_out : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin across iin through n_in to electrical_ref;
  quantity v1 across i1 through n_in to n_out;
  quantity vc across ic through n_in to n_out;
  quantity vout across i2 through n_out to electrical_ref;
begin
  vin == 1.0 + ac_in;
  v1 == r1 * i1;
  ic == c1 * vc'dot;
  vout == r2 * i2;
end architecture;
