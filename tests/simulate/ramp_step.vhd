-- 'ramp of a signal step 0 -> 1 at 1 ms (rise 0.5 ms) and back 1 -> 0 at 3 ms (fall 1 ms);
-- 'slew of the same signal with slopes +2000/s and -1000/s (the same ramps); 'ramp without
-- arguments follows at once.
entity ramp_step is
end entity ramp_step;

architecture test of ramp_step is
  signal s : real := 0.0;
  quantity r, l, i : real;
begin
  r == s'ramp(0.5e-3, 1.0e-3);
  l == s'slew(2000.0, -1000.0);
  i == s'ramp;
  s <= 1.0 after 1 ms, 0.0 after 3 ms;
end architecture test;
