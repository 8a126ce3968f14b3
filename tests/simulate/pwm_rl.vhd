-- An RL load driven by a 50 % PWM voltage (v for half a period, 0 for the other half). In the
-- periodic steady state, with a = (period / 2) / (l / r), the current swings between
-- i_min = (v / r) e^-a / (1 + e^-a) (end of the off half) and i_max = (v / r) / (1 + e^-a).
library ieee;
use ieee.electrical_systems.all;

entity pwm_rl is
  generic (v : real := 10.0; r : real := 2.0; l : real := 10.0e-3; period : real := 5.0e-3);
end entity pwm_rl;

architecture test of pwm_rl is
  terminal a : electrical;
  quantity v_src across i_src through a to electrical_ref;
  quantity v_load across i_load through a to electrical_ref;
  signal drive : boolean := false;
begin
  if drive use
    v_src == v;
  else
    v_src == 0.0;
  end use;
  v_load == r * i_load + l * i_load'dot;
  break i_load => 0.0;
  break on drive;

  pwm : process
  begin
    drive <= true;
    wait for period / 2.0 * 1 sec;
    drive <= false;
    wait for period / 2.0 * 1 sec;
  end process pwm;
end architecture test;
