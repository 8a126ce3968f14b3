-- vams: stop 3 ms
--
-- A frequency-shift-keying modulator as the textbooks write it: a free quantity `phi`
-- whose derivative an equation sets (`phi'dot == w`), switched by a digital input. No
-- `x'dot = 0` quiescent point exists (the equation says phi'dot = w), so phi starts at its
-- initial value 0.0, as if `break phi => 0.0` were written, and grows at w. The phase after
-- 1 ms at 1 kHz and 1 ms at 2 kHz is 2 pi (1 + 2) exactly.

library ieee;
use ieee.math_real.all;
library ieee_proposed;
use ieee_proposed.electrical_systems.all;

entity tb_free_running_phase is
end entity tb_free_running_phase;

architecture test of tb_free_running_phase is
  constant fc : real := 1.0e3;
  signal d_in : bit := '0';
  quantity phi : real;
  terminal a_out : electrical;
  quantity vout across iout through a_out;
begin
  if d_in = '0' use
    phi'dot == math_2_pi * fc;
  else
    phi'dot == math_2_pi * 2.0 * fc;
  end use;
  break on d_in;
  vout == sin(phi);

  stimulus : process
  begin
    wait for 1 ms;
    d_in <= '1';
    wait;
  end process stimulus;

  check : process
  begin
    wait for 0 ns;
    assert abs(phi) < 1.0e-12 report "phi at t = 0: " & real'image(phi) severity error;
    wait for 2 ms;
    assert abs(phi - math_2_pi * 3.0) < 1.0e-6 * math_2_pi * 3.0
      report "phi at 2 ms: " & real'image(phi) severity error;
    assert abs(vout) < 1.0e-5 report "vout at 2 ms: " & real'image(vout) severity error;
    wait;
  end process check;
end architecture test;
