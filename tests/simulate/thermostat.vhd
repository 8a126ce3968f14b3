-- A room heated towards t_on while the heater is on and cooling towards t_off while it is off;
-- the thermostat switches off above t_high and on again below t_low (hysteresis). From
-- t0 < t_low the switch times are t1 = tau ln((t_on - t0) / (t_on - t_high)), then
-- alternately tau ln((t_high - t_off) / (t_low - t_off)) and tau ln((t_on - t_low) / (t_on - t_high)).
entity thermostat is
  generic (tau : real := 100.0; t_on : real := 30.0; t_off : real := 10.0;
           t_low : real := 19.0; t_high : real := 21.0; t0 : real := 15.0);
end entity thermostat;

architecture test of thermostat is
  quantity temp : real;
  signal heater : boolean := true;
begin
  if heater use
    temp'dot == (t_on - temp) / tau;
  else
    temp'dot == (t_off - temp) / tau;
  end use;
  break temp => t0;
  break on heater;

  control : process (temp'above(t_high), temp'above(t_low))
  begin
    if temp'above(t_high) and heater then
      heater <= false;
      report "off";
    elsif not temp'above(t_low) and not heater then
      heater <= true;
      report "on";
    end if;
  end process control;
end architecture test;
