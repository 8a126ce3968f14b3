-- tb_rc: a voltage step through r into c, the capacitor's voltage measured; `mode` selects
-- the experiment: 0 charges from 0 V to v_step at t_on, 1 discharges from v_step at t_on.
-- The fit tests recover r and c (and v_step) from synthetic captures of this testbench.

library ieee;
use ieee.electrical_systems.all;

entity tb_rc is
  generic (
    r      : real := 1.0e3;    -- [Ohm]
    c      : real := 1.0e-6;   -- [F]
    v_step : real := 5.0;      -- [V]
    t_on   : real := 1.0e-3;   -- [s] when the source switches
    mode   : integer := 0      -- 0: charge, 1: discharge
  );
end entity tb_rc;

architecture bench of tb_rc is
  terminal a, b : electrical;
  quantity vin across iin through a to electrical_ref;
  quantity vout across ir through a to b;
  quantity vc across ic through b to electrical_ref;
  signal switched : boolean := false;
begin
  switched <= true after t_on * 1 sec;
  charge : if mode = 0 generate
    if switched use
      vin == v_step;
    else
      vin == 0.0;
    end use;
  end generate;
  discharge : if mode /= 0 generate
    if switched use
      vin == 0.0;
    else
      vin == v_step;
    end use;
  end generate;
  vout == r * ir;
  ic == c * vc'dot;
  break on switched;
end architecture bench;
