-- vams: stop 6 sec
-- vams: panel vref, vfb
-- vams: panel v_conn1, v_conn2, v_supply
-- vams: panel v_motor
-- vams: panel i_motor
-- vams: panel ov
--
-- tb_tracking: the paper's Figure 6.  Battery 12 V, reflector at position 0,
-- reference 1.0 V; the motor runs until vfb enters the deadband and the brake
-- and the constant friction stop it at the deadband's lower edge (vref -
-- deadband).  At t = 3 s the reference rises by 1 V and the servo tracks again.
-- About 10.5 V across the motor while tracking; shorted to the supply when
-- stopped.  Self-checking: the assertions below fail when this breaks.
-- Expected figures: see the comment block of headlight_system.vhd.

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;
use ieee.math_real.all;

entity tb_tracking is
  generic (
    -- motor parameters a user may override (models/headlight.params); defaults as dc_motor's
    r          : real := 4.0;     -- [Ohm] armature resistance
    l          : real := 3.0e-3;  -- [H] armature inductance
    kt         : real := 0.015;   -- [N m/A] torque constant
    ke         : real := 0.015;   -- [V s/rad] back-EMF constant
    d          : real := 1.5e-6;  -- [N m s/rad] viscous damping
    j          : real := 1.0e-6;  -- [kg m2] rotor inertia
    tcst_motor : real := 0.5e-3   -- [N m] motor constant friction (constant_friction)
  );
end entity tb_tracking;

architecture bench of tb_tracking is
  constant deadband : real := 0.1;  -- [V] passed to the IC, used by the checks
  constant vref0    : real := 1.0;  -- [V] first set point
  constant dv_ref   : real := 1.0;  -- [V] the reference step at 3 s

  -- check tolerances
  constant v_track   : real := 10.5;  -- [V] motor voltage while tracking (PAPER.md section 1)
  constant tol_track : real := 0.5;   -- [V]
  constant tol_stop  : real := 0.05;  -- [V] how far past the lower edge vfb may stop (braking overshoot)

  terminal bat, supply, conn1, conn2, ref, fb : electrical;
  quantity vref     across ref   to electrical_ref;
  quantity vfb      across fb    to electrical_ref;
  quantity v_conn1  across conn1 to electrical_ref;
  quantity v_conn2  across conn2 to electrical_ref;
  quantity v_motor  across conn1 to conn2;
  quantity v_bat    across bat    to electrical_ref;
  quantity v_supply across supply to electrical_ref;
  quantity i_motor  : current;
  signal ov : boolean;
begin
  dut : entity work.headlight_system(structural)
    generic map (r => r, l => l, kt => kt, ke => ke, d => d, j => j,
                 tcst_motor => tcst_motor, deadband => deadband,
                 v_bat0 => 12.0, vref0 => vref0, t_ref_step => 3.0, dv_ref => dv_ref)
    port map (bat => bat, supply => supply, conn1 => conn1, conn2 => conn2,
              ref => ref, fb => fb, i_motor => i_motor, ov => ov);

  check : process
    variable vfb_rest : real;  -- [V] feedback when the motor has come to rest
  begin
    assert not ov report "overvoltage at 12 V" severity error;

    -- t = 0.6 s: first run, mid-travel
    wait for 0.6 sec;
    assert abs(v_motor - v_track) < tol_track
      report "0.6 s: v_motor = " & real'image(v_motor) & " V while tracking, expected about 10.5 V"
      severity error;
    assert i_motor > 0.05
      report "0.6 s: motor not driven forward, i_motor = " & real'image(i_motor) & " A"
      severity error;

    -- t = 2.0 s: at rest at the lower edge of the deadband, braked
    wait for 1.4 sec;
    assert vfb > vref - deadband - 0.005 and vfb < vref - deadband + tol_stop
      report "2.0 s: vfb = " & real'image(vfb) & " V, not at the deadband's lower edge "
             & real'image(vref - deadband) & " V"
      severity error;
    assert abs(v_motor) < 0.01 and abs(i_motor) < 0.01
      report "2.0 s: motor not at rest, v_motor = " & real'image(v_motor) & " V"
      severity error;
    assert v_conn1 > v_supply - 0.05 and v_conn2 > v_supply - 0.05
      report "2.0 s: motor not short-circuited to the supply (brake)"
      severity error;
    vfb_rest := vfb;

    -- t = 2.9 s: still there, no creep, no chatter
    wait for 0.9 sec;
    assert abs(vfb - vfb_rest) < 1.0e-3 and abs(i_motor) < 0.01
      report "2.9 s: not held at rest, vfb moved by " & real'image(vfb - vfb_rest) & " V"
      severity error;
    assert abs(vfb - (vref - deadband)) < tol_stop
      report "2.9 s: vfb = " & real'image(vfb) & " V, not at the deadband's lower edge"
      severity error;
    assert abs(vref - vref0) < 1.0e-9
      report "2.9 s: reference changed before 3 s"
      severity error;

    -- t = 3.5 s: the reference rose by 1 V, second run, mid-travel
    wait for 0.6 sec;
    assert abs(vref - (vref0 + dv_ref)) < 1.0e-9
      report "3.5 s: reference did not rise by 1 V"
      severity error;
    assert abs(v_motor - v_track) < tol_track and i_motor > 0.05
      report "3.5 s: not tracking, v_motor = " & real'image(v_motor) & " V"
      severity error;

    -- t = 5.0 s: at rest at the new lower edge, braked
    wait for 1.5 sec;
    assert vfb > vref - deadband - 0.005 and vfb < vref - deadband + tol_stop
      report "5.0 s: vfb = " & real'image(vfb) & " V, not at the deadband's lower edge "
             & real'image(vref - deadband) & " V"
      severity error;
    assert abs(v_motor) < 0.01 and abs(i_motor) < 0.01
      report "5.0 s: motor not at rest, v_motor = " & real'image(v_motor) & " V"
      severity error;
    assert v_conn1 > v_supply - 0.05 and v_conn2 > v_supply - 0.05
      report "5.0 s: motor not short-circuited to the supply (brake)"
      severity error;
    vfb_rest := vfb;

    -- t = 5.9 s: still there
    wait for 0.9 sec;
    assert abs(vfb - vfb_rest) < 1.0e-3 and abs(i_motor) < 0.01
      report "5.9 s: not held at rest, vfb moved by " & real'image(vfb - vfb_rest) & " V"
      severity error;
    assert abs(vfb - (vref - deadband)) < tol_stop
      report "5.9 s: vfb = " & real'image(vfb) & " V, not at the deadband's lower edge"
      severity error;
    assert not ov
      report "5.9 s: overvoltage at 12 V"
      severity error;
    wait;
  end process check;
end architecture bench;
