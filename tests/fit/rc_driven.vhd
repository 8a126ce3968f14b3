-- An RC low-pass whose input is whatever the bench applied: the table `drive` of time
-- (`vams fit --drive drive=vin` fills it from the capture's input column). Alone it runs a
-- 5 V step at 1 ms and checks the response at 9 ms against the closed form.
-- vams: stop 10 ms
library ieee;
use ieee.electrical_systems.all;
use ieee.math_real.all;
library vams;
use vams.tables.all;

entity tb_rc_driven is
  generic (
    r     : real := 1.0e3;
    c     : real := 1.0e-6;
    drive : real_vector := (0.0, 0.0, 1.0e-3, 0.0, 1.001e-3, 5.0)
  );
end entity tb_rc_driven;

architecture bench of tb_rc_driven is
  terminal n_in, n_out : electrical;
  quantity vin across iin through n_in to electrical_ref;
  quantity vr across ir through n_in to n_out;
  quantity vout across ic through n_out to electrical_ref;
begin
  vin == pwl(drive, now);
  vr == r * ir;
  ic == c * vout'dot;

  check : process
    constant expected : real := 5.0 * (1.0 - exp(-8.0e-3 / (r * c)));
  begin
    wait for 9 ms;
    assert abs(vout - expected) < 1.0e-3
      report "vout = " & real'image(vout) & " at 9 ms, the closed form says " & real'image(expected)
      severity error;
    wait;
  end process;
end architecture bench;
