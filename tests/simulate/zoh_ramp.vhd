-- 'zoh of a ramp x = 1000 t sampled every 1 ms from 0.5 ms: staircase 1000 (0.5e-3 + k 1e-3)
-- held between samples; 'ztf of the constant 1 through the accumulator 1 / (1 - z^-1):
-- 1, 2, 3, ... after each sample.
entity zoh_ramp is
end entity zoh_ramp;

architecture test of zoh_ramp is
  constant num : real_vector := (0 => 1.0);
  constant den : real_vector := (1.0, -1.0);
  quantity x, one, held, acc : real;
begin
  x == 1000.0 * now;
  one == 1.0;
  held == x'zoh(1.0e-3, 0.5e-3);
  acc == one'ztf(num, den, 1.0e-3);
end architecture test;
