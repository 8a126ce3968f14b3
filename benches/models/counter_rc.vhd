-- vams: stop 1 ms
--
-- counter_rc: an event-heavy mixed run for the streaming-output benchmark (issue 23). A
-- counter steps every 1 ns (1e6 events per simulated millisecond) beside an RC low pass
-- (1 kOhm, 1 uF) driven by a 1 V step at 10 us. The counter's signal is not read by the
-- equations, so every row of the output is an event of the digital part.

library ieee;
use ieee.electrical_systems.all;

entity counter_rc is
end entity counter_rc;

architecture bench of counter_rc is
  terminal inp, outp : electrical;
  quantity vin across iin through inp to electrical_ref;
  quantity vr across ir through inp to outp;
  quantity vout across ic through outp to electrical_ref;
  signal drive : real := 0.0;  -- [V] the source's value
  signal count : integer := 0;
begin
  vin == drive;
  vr == 1.0e3 * ir;
  ic == 1.0e-6 * vout'dot;

  step : process
  begin
    wait for 10 us;
    drive <= 1.0;
    wait;
  end process step;

  counter : process
  begin
    wait for 1 ns;
    count <= (count + 1) mod 1000000;
  end process counter;
end architecture bench;
