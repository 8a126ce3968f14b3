-- An RC low-pass driven by a piecewise-linear source (`vams.tables.pwl` of `now`): a ramp
-- from 0 to 5 V over 0.5 ms starting at 1 ms, held, then down to 2 V over 1 ms from 4 ms.
-- `shaped` is a table of a quantity (a saturating characteristic of the capacitor voltage),
-- and `sampled` a process that reads the same table every 250 us.
library ieee;
use ieee.electrical_systems.all;
library vams;
use vams.tables.all;

entity pwl_rc is
  generic (
    drive : real_vector := (0.0, 0.0, 1.0e-3, 0.0, 1.5e-3, 5.0, 4.0e-3, 5.0, 5.0e-3, 2.0);
    r     : real := 1.0e3;
    c     : real := 1.0e-6
  );
end entity pwl_rc;

architecture a of pwl_rc is
  terminal n1, n2 : electrical;
  quantity vin across iin through n1 to electrical_ref;
  quantity vr across ir through n1 to n2;
  quantity vc across ic through n2 to electrical_ref;
  quantity shaped : real;
  signal sampled : real := 0.0;
begin
  vin == pwl(drive, now);
  vr == r * ir;
  ic == c * vc'dot;
  shaped == pwl((0.0, 0.0, 1.0, 2.0, 3.0, 3.0), vc);

  sample : process
  begin
    wait for 250 us;
    sampled <= pwl(drive, real(now / 1 fs) * 1.0e-15);
  end process;
end architecture a;
