-- vams: stop 12 sec
--
-- A limiter inside a feedback loop, as the case studies' servo amplifiers write it: the
-- limiter's equations switch on its own input (`if vin > limit_high use`), with `break on
-- vin'above(limit_high)`. A ramp `x` drives `vin == x - 0.5 * vout`. Before the limit,
-- vout = vin = x / 1.5; the limit is reached at x = 7.2 (t = 7.2 s); after it vout stays at
-- 4.8 plus a slope of 1e-4. Each restart at the crossing puts vin a rounding error on one
-- side of 4.8 or the other, depending on the branch: the run must settle there, not flip
-- the `'above` forever. The second testbench makes that rounding error on purpose: its two
-- branches put vin 2e-11 on either side of the threshold at the crossing, which flipped the
-- `'above` back at every restart ("did not settle at t = 4.8 s: 10000 restarts"). A restart
-- within tolerance of a threshold now leaves the `'above` as the crossing set it.

library ieee_proposed;
use ieee_proposed.electrical_systems.all;

entity tb_limiter_in_a_loop is
end entity tb_limiter_in_a_loop;

architecture test of tb_limiter_in_a_loop is
  constant limit_high : real := 4.8;
  constant slope : real := 1.0e-4;
  quantity x : real;
  quantity vin, vout : real;
begin
  break x => 0.0;
  x'dot == 1.0;
  vin == x - 0.5 * vout;
  if vin > limit_high use
    vout == limit_high + slope * (vin - limit_high);
  else
    vout == vin;
  end use;
  break on vin'above(limit_high);

  check : process
  begin
    wait for 6 sec;
    assert abs(vout - 6.0 / 1.5) < 1.0e-6 report "vout at 6 s: " & real'image(vout) severity error;
    wait for 4 sec;
    -- x = 10: vin = 10 - 0.5 (4.8 + 1e-4 (vin - 4.8)), so vin - 4.8 = 2.8 / (1 + 0.5e-4).
    assert abs(vin - (4.8 + 2.8 / (1.0 + 0.5e-4))) < 1.0e-6
      report "vin at 10 s: " & real'image(vin) severity error;
    assert abs(vout - (4.8 + 1.0e-4 * 2.8 / (1.0 + 0.5e-4))) < 1.0e-6
      report "vout at 10 s: " & real'image(vout) severity error;
    wait;
  end process check;
end architecture test;

entity tb_threshold_restart is
end entity tb_threshold_restart;

architecture test of tb_threshold_restart is
  quantity x, vin : real;
begin
  break x => 0.0;
  x'dot == 1.0;
  if vin'above(4.8) use
    vin == x - 2.0e-11;
  else
    vin == x;
  end use;
  break on vin'above(4.8);

  check : process
  begin
    wait for 6 sec;
    assert vin'above(4.8) report "vin'above(4.8) at 6 s is false" severity error;
    assert abs(vin - 6.0) < 1.0e-6 report "vin at 6 s: " & real'image(vin) severity error;
    wait;
  end process check;
end architecture test;
