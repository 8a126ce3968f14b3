-- vams: stop 5 ms
--
-- rc: a 1 kOhm / 1 uF low pass (time constant 1 ms) driven by a source that steps from 0 to
-- 1 V at 1 ms.  For t > 1 ms: vout = 1 - exp(-(t - 1 ms) / 1 ms).

library ieee;
use ieee.electrical_systems.all;

entity rc is
  generic (
    r : real := 1.0e3;   -- [Ohm]
    c : real := 1.0e-6   -- [F]
  );
end entity rc;

architecture behavioral of rc is
  terminal inp, outp : electrical;
  quantity vin across iin through inp to electrical_ref;
  quantity vr across ir through inp to outp;
  quantity vout across ic through outp to electrical_ref;
  signal drive : real := 0.0;  -- [V] the source's value
  signal high : boolean := false;
begin
  vin == drive;
  vr == r * ir;
  ic == c * vout'dot;

  step : process
  begin
    wait for 1 ms;
    drive <= 1.0;
    high <= true;
    wait;
  end process step;
end architecture behavioral;
