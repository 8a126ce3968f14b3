-- headlight_system: the assembled headlight-leveling servo (PAPER.md section 1),
-- used by tb_tracking and tb_overvoltage.
--
-- Netlist (electrical nodes to electrical_ref, shaft to rotational_v_ref,
-- rack to translational_v_ref):
--   battery            bat
--   diode              bat -> supply          reverse-battery diode
--   dashboard_pot      ref                    the driver's reference
--   hbridge_ic         supply, out1, out2     inputs ref and fb
--   wiring_harness     out1 -> h1, out2 -> conn2
--   (ammeter)          h1 -> conn1            i_motor
--   dc_motor           conn1 -> conn2, shaft
--   constant_friction  shaft
--   gear_inertia       shaft
--   rack_pinion_gear   shaft -> rack
--   spring             rack                   return spring, relaxed at position 0
--   reflector_mass     rack
--   potentiometer      rack -> fb             feedback
--
-- Ports: the nodes a testbench observes (bat, supply, conn1, conn2, ref, fb,
-- all to electrical_ref), the motor current i_motor (into conn1, measured by a
-- zero-volt branch between the harness and the motor) and the IC's ov state.
-- Every parameter is a generic passed down to its model; the defaults are the
-- models' defaults (see each model for the reason of each value).
--
-- Expected behaviour with the defaults (independent reference:
-- models/reference/headlight_check.py, backward Euler on the same equations;
-- a 4 x finer step changes these figures in the 4th digit at most):
--   tb_tracking (battery 12 V; vref 1.0 V, 2.0 V from 3 s; reflector at 0):
--     inrush peak |i_motor| 1.48 A
--     tracking: v_motor 10.56 V, i_motor 0.231 A, v_supply 11.30 V, 6135 rpm,
--               vfb rising at 0.80 V/s
--     run 1: vfb enters the deadband (0.90 V) at 1.161 s, shaft at rest at 1.254 s,
--            vfb at 2.9 s = 0.9244 V (lower edge 0.90 V, overshoot 0.024 V)
--     run 2: vfb enters the deadband (1.90 V) at 4.256 s, shaft at rest at 4.349 s,
--            vfb at 5.9 s = 1.9243 V (overshoot 0.024 V)
--     at rest: motor shorted to the supply (v_conn1 = v_conn2 = v_supply within
--            30 uV, |v_motor| < 1e-5 V), |w| < 1.3e-3 rad/s, vfb drift < 3e-6 V,
--            no switching (no chatter)
--   tb_overvoltage (battery 0->12 V 0-1 s, 12->24 V 2-3 s, 24->12 V 3-4 s,
--                   12->0 V 5.5-7 s; vref 4.8 V; reflector at 0):
--     at 1.5 s: v_bat - v_supply 0.697 V, v_motor 10.56 V, i_motor 0.232 A
--     ov true at 2.5682 s (v_supply 18.100 V, v_bat 18.82 V, motor at 9970 rpm);
--       freewheel through the clamp diodes (conn1 at -0.6 V, conn2 at 18.9 V):
--       0.339 A -> below 1 mA within 39 us, then |i_motor| ~ 15 uA (leakage);
--       v_motor = back-EMF (15.6 V falling), motor coasts to rest at 2.985 s
--     ov false at 3.4921 s (v_supply 17.500 V, v_bat 18.10 V); restart peak
--       |i_motor| 2.28 A (stall current at 17.5 V)
--     at 4.5 s: driving again, v_motor 10.55 V; at 6.0 s (v_bat 8 V): v_motor 6.78 V;
--     at 7.9 s: v_bat = v_supply = 0 V, vfb 4.19 V (never reached 4.7 V)

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity headlight_system is
  generic (
    -- dc_motor
    r                 : real := 4.0;      -- [Ohm] armature resistance (dc_motor)
    l                 : real := 3.0e-3;   -- [H] armature inductance (dc_motor)
    kt                : real := 0.015;    -- [N m/A] torque constant (dc_motor)
    ke                : real := 0.015;    -- [V s/rad] back-EMF constant (dc_motor)
    d                 : real := 1.5e-6;   -- [N m s/rad] viscous damping (dc_motor)
    j                 : real := 1.0e-6;   -- [kg m2] rotor inertia (dc_motor)
    -- constant_friction
    tcst_motor        : real := 0.5e-3;   -- [N m] motor part of the constant friction (constant_friction)
    tcst_system       : real := 2.0e-3;   -- [N m] gear part, referred to the motor shaft (constant_friction)
    w_s               : real := 0.1;      -- [rad/s] smoothing velocity scale (constant_friction)
    -- gear, spring, reflector, feedback pot
    jg                : real := 0.3e-6;   -- [kg m2] gear inertia at the motor shaft (gear_inertia)
    gear_ratio        : real := 60.0;     -- [1] reduction (rack_pinion_gear)
    radius_p          : real := 1.2e-4;   -- [m] pinion radius (rack_pinion_gear)
    ks                : real := 5000.0;   -- [N/m] return spring (spring)
    mass_extrapolated : real := 0.3;      -- [kg] reflector mass at the rack (reflector_mass)
    k_pot             : real := 625.0;    -- [V/m] feedback pot factor (potentiometer)
    x0                : real := 0.0;      -- [m] reflector position at t = 0; the paper's runs start at 0
    -- wiring_harness
    r_line            : real := 0.1;      -- [Ohm] per line (wiring_harness)
    l_line            : real := 3.75e-6;  -- [H] per line (wiring_harness)
    -- hbridge_ic
    deadband          : real := 0.1;      -- [V] (hbridge_ic)
    hysteresis        : real := 0.05;     -- [V] (hbridge_ic)
    ovhi_off          : real := 18.1;     -- [V] (hbridge_ic)
    ovlo_off          : real := 17.5;     -- [V] (hbridge_ic)
    -- battery profile (battery): constant 12 V by default
    v_bat0            : real := 12.0;     -- [V] battery voltage at t = 0
    t1  : real := -1.0;  tr1 : real := 0.0;  v1 : real := 12.0;  -- [s], [s], [V] segment 1 (battery)
    t2  : real := -1.0;  tr2 : real := 0.0;  v2 : real := 12.0;  -- [s], [s], [V] segment 2 (battery)
    t3  : real := -1.0;  tr3 : real := 0.0;  v3 : real := 12.0;  -- [s], [s], [V] segment 3 (battery)
    t4  : real := -1.0;  tr4 : real := 0.0;  v4 : real := 12.0;  -- [s], [s], [V] segment 4 (battery)
    -- dashboard_pot
    vref0             : real := 1.0;      -- [V] reference at t = 0 (dashboard_pot)
    t_ref_step        : real := -1.0;     -- [s] time of the reference step; < 0: none (dashboard_pot)
    dv_ref            : real := 1.0;      -- [V] reference step (dashboard_pot)
    tr_ref            : real := 0.0       -- [s] duration of the reference change; 0: a step (dashboard_pot)
  );
  port (
    terminal bat, supply, conn1, conn2, ref, fb : electrical;
    quantity i_motor : out current;   -- [A] into the motor at conn1
    signal ov        : out boolean    -- the IC's overvoltage state
  );
end entity headlight_system;

architecture structural of headlight_system is
  terminal out1, out2, h1 : electrical;
  terminal shaft : rotational_v;
  terminal rack  : translational_v;
  quantity v_sense across i_sense through h1 to conn1;  -- ammeter
begin
  v_sense == 0.0;
  i_motor == i_sense;

  u_battery : entity work.battery(behavioral)
    generic map (v_init => v_bat0,
                 t1 => t1, tr1 => tr1, v1 => v1, t2 => t2, tr2 => tr2, v2 => v2,
                 t3 => t3, tr3 => tr3, v3 => v3, t4 => t4, tr4 => tr4, v4 => v4)
    port map (pos => bat, neg => electrical_ref);

  u_diode : entity work.diode(behavioral)
    port map (anode => bat, cathode => supply);

  u_ic : entity work.hbridge_ic(behavioral)
    generic map (deadband => deadband, hysteresis => hysteresis,
                 ovhi_off => ovhi_off, ovlo_off => ovlo_off)
    port map (vs => supply, gnd => electrical_ref, out1 => out1, out2 => out2,
              ref_in => ref, fb_in => fb, ov => ov);

  u_harness : entity work.wiring_harness(behavioral)
    generic map (r_line => r_line, l_line => l_line)
    port map (a1 => out1, b1 => h1, a2 => out2, b2 => conn2);

  u_motor : entity work.dc_motor(behavioral)
    generic map (r => r, l => l, kt => kt, ke => ke, d => d, j => j)
    port map (p => conn1, n => conn2, shaft => shaft);

  u_friction : entity work.constant_friction(behavioral)
    generic map (tcst_motor => tcst_motor, tcst_system => tcst_system, w_s => w_s)
    port map (shaft => shaft);

  u_gear_inertia : entity work.gear_inertia(behavioral)
    generic map (jg => jg)
    port map (shaft => shaft);

  u_gear : entity work.rack_pinion_gear(behavioral)
    generic map (gear_ratio => gear_ratio, radius_p => radius_p)
    port map (pinion => shaft, rack => rack);

  u_spring : entity work.spring(behavioral)
    generic map (ks => ks, x0 => x0)  -- relaxed at position 0
    port map (p => rack, n => translational_v_ref);

  u_reflector : entity work.reflector_mass(behavioral)
    generic map (mass_extrapolated => mass_extrapolated)
    port map (p => rack);

  u_feedback_pot : entity work.potentiometer(behavioral)
    generic map (k => k_pot, x0 => x0)
    port map (slider => rack, wiper => fb);

  u_dashboard_pot : entity work.dashboard_pot(behavioral)
    generic map (v_set0 => vref0, t_step => t_ref_step, dv_step => dv_ref, tr_step => tr_ref)
    port map (wiper => ref);
end architecture structural;
