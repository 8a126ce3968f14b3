-- schmitt: an amplifier with positive feedback, vout = a tanh(k (vin + b vout)), bistable
-- where a b k > 1. Its switching thresholds are the folds of vin = u - a b tanh(k u)
-- (u = vin + b vout): vin = +-(a b tanh(k u0) - u0) with cosh(k u0)^2 = a b k. Swept up,
-- vout stays low until vin passes the upper threshold; swept down, high until the lower.
-- vams: stop 1 ms
library ieee;
use ieee.math_real.all;
entity tb_schmitt is
  generic (vin_level : real := -1.0; a : real := 5.0; b : real := 0.1; k : real := 10.0);
end entity;
architecture bench of tb_schmitt is
  quantity vin, vout : real;
begin
  vin == vin_level;
  vout == a * tanh(k * (vin + b * vout));
end architecture;
