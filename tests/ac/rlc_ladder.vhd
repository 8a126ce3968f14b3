-- rlc_ladder: n sections of a series R-L and a shunt C (a lumped transmission line), driven
-- by a spectral source; compared with ngspice's `.ac` of the same ladder in tests/it/ac.rs.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_rlc_ladder is
  generic (n : positive := 20; r : real := 1.0; l : real := 1.0e-3; c : real := 1.0e-6);
end entity;
architecture bench of tb_rlc_ladder is
  terminal node : electrical_vector(0 to n);
  terminal mid : electrical_vector(1 to n);
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin across iin through node(0) to electrical_ref;
  quantity vout across node(n) to electrical_ref;
begin
  vin == ac_in;
  sections : for k in 1 to n generate
    quantity vr across ir through node(k - 1) to mid(k);
    quantity vl across il through mid(k) to node(k);
    quantity vc across ic through node(k) to electrical_ref;
  begin
    vr == r * ir;
    vl == l * il'dot;
    ic == c * vc'dot;
  end generate;
end architecture;
