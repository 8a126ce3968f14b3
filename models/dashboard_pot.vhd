-- dashboard_pot: the driver's reference setting, a potentiometer on the
-- dashboard fed from its own regulated supply.
--
-- Conservation (electrical): branch wiper -> electrical_ref, voltage v across,
-- current i through (an ideal source: the IC's REF input draws no current).
--   v = setting,  setting = v_set0, and v_set0 + dv_step from t_step on
-- The step is a discontinuity of v: break on setting.

library ieee;
use ieee.electrical_systems.all;

entity dashboard_pot is
  generic (
    v_set0  : real := 1.0;   -- [V] reference at t = 0; the tracking run's first set point
    t_step  : real := -1.0;  -- [s] time at which the driver turns the dial; < 0: never
    dv_step : real := 1.0    -- [V] change of the reference at t_step; the paper's +1 V (Figure 6)
  );
  port (terminal wiper : electrical);
end entity dashboard_pot;

architecture behavioral of dashboard_pot is
  quantity v across i through wiper to electrical_ref;
  signal setting : real := v_set0;  -- [V]
begin
  v == setting;

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
