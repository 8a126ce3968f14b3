-- inverting_amp: an inverting amplifier, op-amp of DC gain a0 and one pole at fp (vout +
-- vout'dot / (2 pi fp) == a0 (vp - vm)), input resistor r1, feedback r2, each resistor's
-- thermal noise in series with it and the op-amp's input noise voltage en at its + input.
-- With D = 1 + a(jw) r1 / (r1 + r2): H_in = H_e1 = -a r2 / ((r1 + r2) D),
-- H_e2 = -a r1 / ((r1 + r2) D), H_en = a / D; the input-referred noise is
-- sqrt(S1 + S2 (r1 / r2)^2 + Sen ((r1 + r2) / r2)^2), whatever a(jw).
-- vams: stop 1 ms
library ieee;
use ieee.math_real.all;
entity tb_inverting_amp is
  generic (r1 : real := 1.0e3; r2 : real := 10.0e3; a0 : real := 1.0e5; fp : real := 10.0;
           temp : real := 300.0; en_psd : real := 1.0e-16);
end entity;
architecture bench of tb_inverting_amp is
  constant boltzmann : real := 1.380649e-23;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity e1 : real noise 4.0 * boltzmann * temp * r1;
  quantity e2 : real noise 4.0 * boltzmann * temp * r2;
  quantity en : real noise en_psd;
  quantity vin, vm, vp, vout, i1, i2 : real;
begin
  vin == 0.5 + ac_in;
  vp == en;
  vin + e1 - vm == r1 * i1;
  vout + e2 - vm == r2 * i2;
  i1 + i2 == 0.0;
  vout + vout'dot / (math_2_pi * fp) == a0 * (vp - vm);
end architecture;
