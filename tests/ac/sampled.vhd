-- sampled: the frequency-domain meaning of the sampled-data attributes, each against its
-- closed form in tests/it/ac.rs (T = 1 ms):
--   held     = vin'zoh(T)                    (1 - e^{-jwT}) / (jwT)
--   filtered = vin'ztf((0.2), (1, -0.8), T)  0.2 / (1 - 0.8 e^{-jwT})
--   loop_out = k (vin - loop_out'zoh(T))     k / (1 + k (1 - e^{-jwT}) / (jwT))
--   fir = vin'ztf((0.25, 0.5, 0.25), (1), T)  0.25 + 0.5 e^{-jwT} + 0.25 e^{-2jwT}
-- vams: stop 10 ms
library ieee;
use ieee.math_real.all;
entity tb_sampled is
  generic (t_s : real := 1.0e-3; k : real := 0.5);
end entity;
architecture bench of tb_sampled is
  constant num : real_vector := (0 => 0.2);
  constant den : real_vector := (1.0, -0.8);
  constant fir_num : real_vector := (0.25, 0.5, 0.25);
  constant one : real_vector := (0 => 1.0);
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin, held, filtered, loop_out, fir : real;
begin
  vin == 1.0 + ac_in;
  held == vin'zoh(t_s);
  filtered == vin'ztf(num, den, t_s);
  loop_out == k * (vin - loop_out'zoh(t_s));
  fir == vin'ztf(fir_num, one, t_s);
end architecture;
