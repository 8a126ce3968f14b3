-- vams: stop 8 sec
-- vams: panel v_bat, v_supply
-- vams: panel v_motor
-- vams: panel i_motor
-- vams: panel vfb
-- vams: panel ov
--
-- tb_overvoltage: the paper's Figure 7.  Battery 0 -> 12 V (0-1 s), 12 -> 24 V
-- (2-3 s), 24 -> 12 V (3-4 s), 12 -> 0 V (5.5-7 s); the supply follows a diode
-- drop below.  Reference 4.8 V with the reflector at 0, so the bridge drives
-- the motor through the whole run except while the supply is above the
-- overvoltage thresholds: from v_supply > ovhi_off until v_supply < ovlo_off
-- the outputs are high-impedance, the motor current decays through the clamp
-- diodes and the motor coasts (the connectors show only its back-EMF).
-- Self-checking: the assertions below fail when this breaks.
-- Expected figures: see the comment block of headlight_system.vhd.

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;
use ieee.math_real.all;

entity tb_overvoltage is
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
end entity tb_overvoltage;

architecture bench of tb_overvoltage is
  constant ovhi_off : real := 18.1;  -- [V] passed to the IC, used by the checks
  constant ovlo_off : real := 17.5;  -- [V] passed to the IC, used by the checks

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
                 tcst_motor => tcst_motor, ovhi_off => ovhi_off, ovlo_off => ovlo_off,
                 v_bat0 => 0.0,
                 t1 => 0.0, tr1 => 1.0, v1 => 12.0,   -- phase 1: 0 -> 12 V
                 t2 => 2.0, tr2 => 1.0, v2 => 24.0,   -- phase 2: 12 -> 24 V
                 t3 => 3.0, tr3 => 1.0, v3 => 12.0,   --          24 -> 12 V
                 t4 => 5.5, tr4 => 1.5, v4 => 0.0,    -- phase 3: 12 -> 0 V
                 vref0 => 4.8)
    port map (bat => bat, supply => supply, conn1 => conn1, conn2 => conn2,
              ref => ref, fb => fb, i_motor => i_motor, ov => ov);

  -- The run, checked at its milestones.
  check : process
  begin
    -- phase 1 done, 12 V: driving, the supply a diode drop below the battery
    wait for 1.5 sec;
    assert not ov
      report "1.5 s: overvoltage at 12 V" severity error;
    assert v_bat - v_supply > 0.5 and v_bat - v_supply < 0.9
      report "1.5 s: supply is " & real'image(v_bat - v_supply) & " V below the battery, expected about 0.7 V"
      severity error;
    assert abs(v_motor - 10.5) < 0.5 and v_conn1 > v_supply - 1.5
      report "1.5 s: not driving, v_motor = " & real'image(v_motor) & " V" severity error;

    -- phase 2, rising: the outputs switch off at ovhi_off
    wait until ov for 1.5 sec;
    assert ov
      report "overvoltage protection did not engage by 3.0 s" severity error;
    assert v_supply > ovhi_off - 0.05 and v_supply < ovhi_off + 0.1
      report "ov engaged at v_supply = " & real'image(v_supply) & " V, expected ovhi_off = "
             & real'image(ovhi_off) & " V" severity error;

    -- 5 ms later: freewheel current decayed through the clamp diodes, motor coasting
    wait for 5 ms;
    assert ov
      report "ov released 5 ms after engaging" severity error;
    assert abs(i_motor) < 1.0e-3
      report "motor current " & real'image(i_motor) & " A 5 ms into ov: outputs not high-impedance"
      severity error;
    assert v_motor > 5.0
      report "no back-EMF 5 ms into ov (v_motor = " & real'image(v_motor) & " V): motor not coasting"
      severity error;

    -- 3.4 s: still locked out; the motor has coasted to rest
    wait for 3.4 sec - now;
    assert ov and v_supply > ovlo_off
      report "3.4 s: ov released above ovlo_off" severity error;
    assert abs(v_motor) < 0.5 and abs(i_motor) < 1.0e-3
      report "3.4 s: motor not coasted to rest, v_motor = " & real'image(v_motor) & " V" severity error;

    -- phase 2, falling: the outputs switch on again below ovlo_off
    wait until not ov for 1.0 sec;
    assert not ov
      report "overvoltage protection did not release by 4.4 s" severity error;
    assert v_supply < ovlo_off + 0.05 and v_supply > ovlo_off - 0.1
      report "ov released at v_supply = " & real'image(v_supply) & " V, expected ovlo_off = "
             & real'image(ovlo_off) & " V" severity error;

    -- 4.5 s, back at 12 V: driving again
    wait for 4.5 sec - now;
    assert not ov and abs(v_motor - 10.5) < 0.5 and i_motor > 0.05
      report "4.5 s: not driving after the overvoltage, v_motor = " & real'image(v_motor) & " V"
      severity error;

    -- phase 3 (6.0 s, battery 8 V): still driving, one connector follows the supply
    wait for 6.0 sec - now;
    assert not ov and v_motor > 5.0 and v_conn1 > v_supply - 1.0
      report "6.0 s: not driving while the battery falls" severity error;

    -- 7.9 s: battery at 0 V
    wait for 7.9 sec - now;
    assert not ov and abs(v_supply) < 0.5 and abs(i_motor) < 1.0e-3
      report "7.9 s: supply or motor not at rest with the battery at 0 V" severity error;
    wait;
  end process check;

  -- Throughout the run: ov set whenever the supply is clearly above ovhi_off,
  -- cleared whenever it is clearly below ovlo_off.
  monitor_high : process
  begin
    wait until v_supply'above(ovhi_off + 0.05);
    assert ov
      report "v_supply above ovhi_off but ov not set" severity error;
  end process monitor_high;

  monitor_low : process
  begin
    wait until not v_supply'above(ovlo_off - 0.05);
    assert not ov
      report "v_supply below ovlo_off but ov still set" severity error;
  end process monitor_low;
end architecture bench;
