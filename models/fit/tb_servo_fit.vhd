-- vams: stop 3.5 sec
-- vams: panel vref, vfb
-- vams: panel v_motor
--
-- tb_servo_fit: the tracking run that `vams fit` needs to see the H-bridge IC's
-- deadband and hysteresis and the feedback pot's factor (models/fit/README.md).
-- The headlight servo of tb_tracking (battery 12 V, reflector at position 0),
-- with a reference that the driver turns slowly instead of stepping:
--   0 s      vref 1.0 V: the motor runs from rest; vfb rises at a slope set by
--            the pot factor k_pot and stops at vref - deadband (plus the
--            braking overshoot)
--   1.5 s    vref ramps by 0.2 V over 1.5 s (0.13 V/s, slower than the servo's
--            0.8 V/s): the motor restarts when the error reaches deadband +
--            hysteresis, catches up and brakes at deadband; twice with the
--            defaults (restarts at 2.06 s and 2.73 s)
--   3.0 s    vref 1.2 V; vfb rests where the last run stopped, between the
--            deadband's edge and the restart threshold
-- The stop levels give the deadband, the restart times the hysteresis, the
-- running slope k_pot.  Few restarts on purpose: each one's time depends on
-- the hysteresis, and a fit whose guess puts the k-th restart a whole cycle
-- off finds a wrong minimum (with a 1 V ramp, 10 restarts, it did).
-- Self-checking: the motor must start at least three times (at 0 s and twice
-- during the ramp) and end at rest inside the window.

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity tb_servo_fit is
  generic (
    deadband   : real := 0.1;    -- [V] the IC's braking window (hbridge_ic)
    hysteresis : real := 0.05;   -- [V] the IC's restart margin beyond it (hbridge_ic)
    k_pot      : real := 625.0   -- [V/m] the feedback pot's factor (potentiometer)
  );
end entity tb_servo_fit;

architecture bench of tb_servo_fit is
  constant vref0    : real := 1.0;  -- [V] first set point
  constant t_ramp   : real := 1.5;  -- [s] the driver starts turning the dial
  constant tr_ramp  : real := 1.5;  -- [s] for this long
  constant dv_ref   : real := 0.2;  -- [V] by this much

  terminal bat, supply, conn1, conn2, ref, fb : electrical;
  quantity vref    across ref   to electrical_ref;
  quantity vfb     across fb    to electrical_ref;
  quantity v_motor across conn1 to conn2;
  quantity i_motor : current;
  signal ov : boolean;
  signal starts : natural := 0;  -- motor starts forward (v_motor rising through 5 V)
begin
  dut : entity work.headlight_system(structural)
    generic map (deadband => deadband, hysteresis => hysteresis, k_pot => k_pot,
                 v_bat0 => 12.0, vref0 => vref0, t_ref_step => t_ramp, dv_ref => dv_ref,
                 tr_ref => tr_ramp)
    port map (bat => bat, supply => supply, conn1 => conn1, conn2 => conn2,
              ref => ref, fb => fb, i_motor => i_motor, ov => ov);

  count : process (v_motor'above(5.0))
  begin
    if v_motor'above(5.0) then
      starts <= starts + 1;
    end if;
  end process count;

  check : process
  begin
    wait for 3.49 sec;
    assert starts >= 3
      report "the motor started " & integer'image(starts)
             & " times: the ramp did not make it brake and restart"
      severity error;
    assert abs(v_motor) < 0.01 and abs(i_motor) < 0.01
      report "3.49 s: motor not at rest, v_motor = " & real'image(v_motor) & " V"
      severity error;
    assert vref - vfb > 0.0 and vref - vfb < deadband + hysteresis
      report "3.49 s: vfb = " & real'image(vfb) & " V not inside the window below vref = "
             & real'image(vref) & " V"
      severity error;
    assert not ov report "overvoltage at 12 V" severity error;
    wait;
  end process check;
end architecture bench;
