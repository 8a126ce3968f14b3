-- vams: stop 8 sec
-- vams: panel vref, vfb
-- vams: panel v_battery, v_supply
-- vams: panel i_motor
-- vams: panel ov
--
-- tb_worst_case: the headlight servo in one run that shows both of the paper's
-- verifications, for the worst-case study of models/sweeps/*.toml (`vams sweep`).
--
--   0 s         battery at v_bat; the reflector starts at 0 and tracks vref = 1 V
--   0.2 - 1.2 s the battery ramps to 24 V: the IC locks its outputs (overvoltage)
--               as the supply passes ovhi_off, mid-travel; the motor coasts
--   1.2 - 2.2 s the battery ramps back to v_bat: the IC releases below ovlo_off
--               and the servo tracks on to the deadband's lower edge (0.9 V)
--   5.0 s       the reference steps to 2 V: the servo tracks again and settles
--               at 1.9 V; the run ends at 8 s
--
-- Records for the metrics: lock_v_bat and release_v_bat, the battery voltage
-- when the IC locks and releases (its thresholds seen from the battery: the
-- supply's thresholds plus the reverse-battery diode's drop at that current),
-- and err = vref - vfb.
--
-- The motor's winding resistance follows its temperature: copper,
-- r = r25 * (1 + 0.0039 * (temperature - 25)) (0.39 %/K, IEC 60228's 0.00393/K
-- at 20 degC rounded). kt = ke (SI units, one motor constant).

library ieee;
use ieee.electrical_systems.all;

entity tb_worst_case is
  generic (
    r25         : real := 4.0;      -- [Ohm] winding resistance at 25 degC
    temperature : real := 25.0;     -- [degC] winding temperature
    l           : real := 3.0e-3;   -- [H] armature inductance
    ke          : real := 0.015;    -- [V s/rad] = [N m/A] motor constant (kt = ke)
    j           : real := 1.0e-6;   -- [kg m2] rotor inertia
    d           : real := 1.5e-6;   -- [N m s/rad] viscous damping
    tcst_motor  : real := 0.5e-3;   -- [N m] motor constant friction
    tcst_system : real := 2.0e-3;   -- [N m] gear constant friction at the motor shaft
    jg          : real := 0.3e-6;   -- [kg m2] gear inertia at the motor shaft
    v_bat       : real := 12.0      -- [V] battery voltage outside the overvoltage pulse
  );
end entity tb_worst_case;

architecture bench of tb_worst_case is
  constant alpha_cu : real := 0.0039;  -- [1/K] copper
  terminal bat, supply, conn1, conn2, ref, fb : electrical;
  quantity vref     across ref    to electrical_ref;
  quantity vfb      across fb     to electrical_ref;
  quantity v_battery across bat   to electrical_ref;
  quantity v_supply across supply to electrical_ref;
  quantity i_motor  : current;
  quantity err      : voltage;
  signal ov : boolean;
  signal lock_v_bat    : real := 0.0;  -- [V] battery voltage at the overvoltage lock
  signal release_v_bat : real := 0.0;  -- [V] battery voltage at the release
begin
  dut : entity work.headlight_system(structural)
    generic map (r => r25 * (1.0 + alpha_cu * (temperature - 25.0)), l => l,
                 kt => ke, ke => ke, d => d, j => j,
                 tcst_motor => tcst_motor, tcst_system => tcst_system, jg => jg,
                 v_bat0 => v_bat,
                 t1 => 0.2, tr1 => 1.0, v1 => 24.0,
                 t2 => 1.2, tr2 => 1.0, v2 => v_bat,
                 vref0 => 1.0, t_ref_step => 5.0, dv_ref => 1.0)
    port map (bat => bat, supply => supply, conn1 => conn1, conn2 => conn2,
              ref => ref, fb => fb, i_motor => i_motor, ov => ov);

  err == vref - vfb;

  thresholds : process
  begin
    wait until ov;
    lock_v_bat <= v_battery;
    wait until not ov;
    release_v_bat <= v_battery;
    wait;
  end process thresholds;
end architecture bench;
