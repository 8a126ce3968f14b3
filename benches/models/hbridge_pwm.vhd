-- hbridge_pwm: a behavioural H-bridge driving a DC motor with PWM, the small-system speed
-- benchmark of issue 3 (benches/hbridge.rs) and its integration test (tests/it/hbridge_pwm.rs).
--
-- Supply vs (v_supply) -> bridge -> motor between out1 and out2 -> ground.  Four switches,
-- each a conductance (1/r_on when on, 1/r_off when off) set by a boolean signal; freewheel
-- diodes across the two switches of the switching leg (out1).  Drive, sign-magnitude:
-- ls2 on and hs2 off all the time; hs1 on for duty * period of every period.  In the off
-- part ls1 is on when synchronous (synchronous freewheeling, piecewise linear), otherwise
-- off, and the motor current freewheels through the diode gnd -> out1.
--   diode:  i = is_sat (exp(v / vt) - 1), continued linearly above v_lin (value and slope
--           match, so no break), which keeps Newton iterates finite.
-- The motor is models/dc_motor.vhd with a free shaft.

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;
use ieee.math_real.all;

entity hbridge_pwm is
  generic (
    v_supply    : real := 12.0;      -- [V] DC supply
    frequency   : real := 20.0e3;    -- [Hz] PWM frequency
    duty        : real := 0.6;       -- [1] fraction of each period with hs1 on
    synchronous : boolean := false;  -- ls1 on in the off part (else the diode freewheels)
    r_on        : real := 0.1;       -- [Ohm] on-resistance of every switch
    r_off       : real := 1.0e6;     -- [Ohm] off-resistance of every switch
    is_sat      : real := 1.0e-8;    -- [A] diode saturation current: about 0.45 V at 0.3 A
    vt          : real := 0.025865;  -- [V] thermal voltage at 300.15 K (ngspice's default)
    v_lin       : real := 1.2        -- [V] diode voltage above which the exponential goes linear
  );
end entity hbridge_pwm;

architecture behavioral of hbridge_pwm is
  terminal vs, out1, out2 : electrical;
  terminal shaft : rotational_v;

  quantity v_sup across i_sup through vs to electrical_ref;
  quantity v_hs1 across i_hs1 through vs to out1;
  quantity v_ls1 across i_ls1 through out1 to electrical_ref;
  quantity v_hs2 across i_hs2 through vs to out2;
  quantity v_ls2 across i_ls2 through out2 to electrical_ref;
  quantity v_dh across i_dh through out1 to vs;               -- freewheel diode of hs1
  quantity v_dl across i_dl through electrical_ref to out1;   -- freewheel diode of ls1

  signal hs1_on, ls1_on : boolean := false;
  constant period : real := 1.0 / frequency;
begin
  v_sup == v_supply;

  break on hs1_on, ls1_on;
  if hs1_on use i_hs1 == v_hs1 / r_on; else i_hs1 == v_hs1 / r_off; end use;
  if ls1_on use i_ls1 == v_ls1 / r_on; else i_ls1 == v_ls1 / r_off; end use;
  i_hs2 == v_hs2 / r_off;
  i_ls2 == v_ls2 / r_on;

  if v_dh > v_lin use
    i_dh == is_sat * (exp(v_lin / vt) * (1.0 + (v_dh - v_lin) / vt) - 1.0);
  else
    i_dh == is_sat * (exp(v_dh / vt) - 1.0);
  end use;
  if v_dl > v_lin use
    i_dl == is_sat * (exp(v_lin / vt) * (1.0 + (v_dl - v_lin) / vt) - 1.0);
  else
    i_dl == is_sat * (exp(v_dl / vt) - 1.0);
  end use;

  motor : entity work.dc_motor(behavioral)
    port map (p => out1, n => out2, shaft => shaft);

  pwm : process
  begin
    hs1_on <= true;
    ls1_on <= false;
    wait for duty * period * 1 sec;
    hs1_on <= false;
    ls1_on <= synchronous;
    wait for (1.0 - duty) * period * 1 sec;
  end process pwm;
end architecture behavioral;
