-- dashboard_pot: the driver's reference setting, a potentiometer on the
-- dashboard fed from its own regulated supply.
--
-- Conservation (electrical): branch wiper -> electrical_ref, voltage v across,
-- current i through (an ideal source: the IC's REF input draws no current).
--   v = setting,  setting = v_set0, and v_set0 + dv_step from t_step on
-- The step is a discontinuity of v: break on setting.  With tr_step > 0 the
-- driver turns the dial slowly: v follows setting'ramp(tr_step), a linear ramp
-- from t_step to t_step + tr_step (models/fit/tb_servo_fit.vhd uses it to make
-- the servo brake and restart).

library ieee;
use ieee.electrical_systems.all;

entity dashboard_pot is
  generic (
    v_set0  : real := 1.0;   -- [V] reference at t = 0; the tracking run's first set point
    t_step  : real := -1.0;  -- [s] time at which the driver turns the dial; < 0: never
    dv_step : real := 1.0;   -- [V] change of the reference at t_step; the paper's +1 V (Figure 6)
    tr_step : real := 0.0    -- [s] duration of the change; 0: a step (the paper's Figure 6)
  );
  port (terminal wiper : electrical);
end entity dashboard_pot;

architecture behavioral of dashboard_pot is
  quantity v across i through wiper to electrical_ref;
  signal setting : real := v_set0;  -- [V]
begin
  stepped : if tr_step <= 0.0 generate
    v == setting;
  end generate;
  ramped : if tr_step > 0.0 generate
    v == setting'ramp(tr_step);
  end generate;

  break on setting;

  dial : process
  begin
    if t_step >= 0.0 then
      wait for t_step * 1 sec;
      setting <= v_set0 + dv_step;
    end if;
    wait;
  end process dial;
end architecture behavioral;
