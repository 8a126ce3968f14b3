-- tb_position_loop: the headlight servo's position loop in the frequency domain, for
-- `vams ac` (Bode plots in docs/) and as an AC unit test of `vams test` (the assertions below;
-- no stop time, so no transient run).
--
-- The plant is the servo's own: wiring harness, dc_motor, gear_inertia, rack_pinion_gear,
-- spring, reflector_mass and the feedback potentiometer, with headlight_system's values. Two
-- parts are replaced by their small-signal descriptions, as a control engineer linearises the
-- loop with the motor running:
--   * the H-bridge IC, which switches the full supply across the motor once |ref - fb| leaves
--     its deadband, by an amplifier of gain v_bat / deadband (12 V per 0.1 V: 120);
--   * the constant friction, a torque of constant magnitude while the motor runs, has no
--     small-signal part and is left out (at standstill its smoothing would act as a
--     viscous damper 17 000 times the motor's own).
-- The motor's electrical and mechanical poles and the position integrator give a type-1
-- loop: the loop gain crosses 0 dB near 1.6 Hz with about 75 degrees of phase margin, and the
-- closed loop tracks the reference with no error at low frequency.
--
-- Loop gain (open loop, the spectral source at the error): vams ac models --top
--   tb_position_loop -g open_loop=true --from 10mHz --to 1kHz --probe vfb
-- Reference to feedback (closed loop): vams ac models --top tb_position_loop
--   --from 10mHz --to 1kHz --probe vfb
-- vams: assert gain_db(vfb, 10mHz) > -0.01
-- vams: assert gain_db(vfb, 100Hz) < -30
-- vams: assert phase_deg(vfb, 1Hz) > -60
library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;

entity tb_position_loop is
  generic (
    open_loop : boolean := false;  -- the source drives the error directly (loop gain)
    v_bat     : real := 12.0;      -- [V] supply across the motor when the bridge is on
    deadband  : real := 0.1        -- [V] the IC's deadband
  );
end entity tb_position_loop;

architecture linearised of tb_position_loop is
  terminal out1, conn1, conn2 : electrical;
  terminal shaft : rotational_v;
  terminal rack : translational_v;
  terminal fb : electrical;
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vfb across fb to electrical_ref;
  quantity err : voltage;
  quantity v_drive across i_drive through out1 to electrical_ref;
begin
  -- The reference is 0 V (the reflector at rest at position 0) plus the small signal.
  closed : if not open_loop generate
    err == ac_in - vfb;
  end generate;
  opened : if open_loop generate
    err == ac_in;
  end generate;
  v_drive == (v_bat / deadband) * err;

  u_harness : entity work.wiring_harness(behavioral)
    port map (a1 => out1, b1 => conn1, a2 => electrical_ref, b2 => conn2);

  u_motor : entity work.dc_motor(behavioral)
    port map (p => conn1, n => conn2, shaft => shaft);

  u_gear_inertia : entity work.gear_inertia(behavioral)
    port map (shaft => shaft);

  u_gear : entity work.rack_pinion_gear(behavioral)
    port map (pinion => shaft, rack => rack);

  u_spring : entity work.spring(behavioral)
    port map (p => rack, n => translational_v_ref);

  u_reflector : entity work.reflector_mass(behavioral)
    port map (p => rack);

  u_feedback_pot : entity work.potentiometer(behavioral)
    port map (slider => rack, wiper => fb);
end architecture linearised;
