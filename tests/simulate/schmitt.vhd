-- A Schmitt trigger (thresholds +-vth) on a sine of amplitude 1 and frequency f: the output
-- rises where sin(2 pi f t) = vth on the way up and falls where it equals -vth on the way down.
library ieee;
use ieee.std_logic_1164.all;
use ieee.math_real.all;

entity schmitt is
  generic (f : real := 50.0; vth : real := 0.5);
end entity schmitt;

architecture test of schmitt is
  quantity vin : real;
  signal q : std_logic := '0';
begin
  vin == sin(math_2_pi * f * now);

  trigger : process (vin'above(vth), vin'above(-vth))
  begin
    if vin'above(vth) and q = '0' then
      q <= '1';
      report "rise";
    elsif not vin'above(-vth) and q = '1' then
      q <= '0';
      report "fall";
    end if;
  end process trigger;
end architecture test;
