-- no_source: an RC low-pass without a spectral source: `vams ac` has nothing to excite.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_no_source is end entity;
architecture bench of tb_no_source is
  terminal n_in, n_out : electrical;
  quantity vin across iin through n_in to electrical_ref;
  quantity vr across ir through n_in to n_out;
  quantity vout across ic through n_out to electrical_ref;
begin
  vin == 2.0;
  vr == 1.0e3 * ir;
  ic == 1.0e-7 * vout'dot;
end architecture;
