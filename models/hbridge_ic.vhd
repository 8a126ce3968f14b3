-- hbridge_ic: behavioral model of a headlight-leveling H-bridge IC
-- (TLE4206/TLE4209 class): window comparator, direction logic, brake,
-- full bridge with clamp diodes, overvoltage lockout.
--
-- Conservation (electrical): every current enters and leaves through the
-- terminals vs, gnd, out1, out2: the four switch branches, the four clamp
-- diodes, and the supply-pin branch (IC supply current and blocking capacitor).
-- The inputs ref_in and fb_in are high impedance (across quantities only).
--
-- Behaviour, with the control error e = v(ref_in) - v(fb_in):
--   * window comparator: the motor runs up (out1 high, out2 low) from
--     e > deadband + hysteresis until e < deadband, and down (out1 low,
--     out2 high) from e < -(deadband + hysteresis) until e > -deadband;
--     |e| < deadband is the deadband, where the motor is braked.
--   * brake: both high sides on, the motor short-circuited to the supply, so
--     that its back-EMF drives a braking current.
--   * overvoltage: from v(vs) > ovhi_off until v(vs) < ovlo_off all four
--     switches are off; the motor current decays through the clamp diodes
--     (gnd -> one output, the other output -> vs) and the motor coasts.
--   * switches: on-resistance when on, r_off when off; the clamp diodes make
--     the high-impedance state physical.
-- The digital state (up, down, ov) lives in processes woken by 'above events;
-- each switch-state change is announced with break.  Not modelled: undervoltage
-- lockout, current-peak blanking, short-circuit and thermal protection, the
-- 1.5-3 us switching delays.

library ieee;
use ieee.electrical_systems.all;

entity hbridge_ic is
  generic (
    deadband    : real := 0.1;      -- [V] half-width of the braking window around vref; programmable with
                                    --     external resistors on TLE4206/TLE4209 (no fixed data-sheet figure);
                                    --     4 x the braking overshoot of the default servo (0.025 V)
    hysteresis  : real := 0.05;     -- [V] error beyond the deadband needed to restart a braked motor;
                                    --     programmable on TLE4206/TLE4209, chosen at half the deadband
    ovhi_off    : real := 18.1;     -- [V] supply at which the outputs switch off; production leveling
                                    --     module: lock at >= 18.1 V (PAPER.md section 7; TDA3629: 18-22 V)
    ovlo_off    : real := 17.5;     -- [V] supply below which the outputs switch on again; production
                                    --     module: release at <= 17.5 V (PAPER.md section 7)
    r_on_hs     : real := 2.2;      -- [Ohm] high-side switch on-resistance: TLE4209's 1.2 V total at 0.4 A,
                                    --     split high:low as TLE4202B's 0.95 V : 0.33 V at 0.3 A (PAPER.md section 7)
    r_on_ls     : real := 0.8;      -- [Ohm] low-side switch on-resistance; same source and split
    r_off       : real := 1.0e6;    -- [Ohm] off-state switch; about 10 uA of leakage at 12 V, keeps the
                                    --     outputs defined when all switches are off
    is_clamp_hs : real := 2.6e-13;  -- [A] clamp diode output -> vs: 1.0 V at 1 A with rs_clamp (TLE4202B,
                                    --     PAPER.md section 7)
    is_clamp_ls : real := 1.2e-11;  -- [A] clamp diode gnd -> output: 0.9 V at 1 A with rs_clamp (TLE4202B)
    rs_clamp    : real := 0.25;     -- [Ohm] clamp diode series resistance; 0.25 V of the drops above at 1 A
    r_q         : real := 1.5e3;    -- [Ohm] IC supply current as a resistance: 8 mA at 12 V, the order of
                                    --     magnitude such ICs draw (chosen; data sheets give ranges)
    c_vs        : real := 47.0e-6   -- [F] blocking capacitor at the vs pin of the module; takes the freewheel
                                    --     current when the outputs go high-impedance (chosen)
  );
  port (
    terminal vs, gnd, out1, out2 : electrical;
    terminal ref_in, fb_in       : electrical;
    signal ov                    : out boolean  -- overvoltage state, for observation
  );
end entity hbridge_ic;

architecture behavioral of hbridge_ic is
  -- inputs (high impedance) and the control error
  quantity v_ref across ref_in to gnd;
  quantity v_fb  across fb_in to gnd;
  quantity e : voltage;

  -- supply pin: IC supply current and blocking capacitor
  quantity v_s across i_s through vs to gnd;

  -- the four switches of the bridge
  quantity v_hs1 across i_hs1 through vs to out1;
  quantity v_ls1 across i_ls1 through out1 to gnd;
  quantity v_hs2 across i_hs2 through vs to out2;
  quantity v_ls2 across i_ls2 through out2 to gnd;

  signal up, down, ov_state : boolean := false;   -- start braked, no overvoltage
  signal hs1_on, hs2_on : boolean := true;         -- consistent with that state
  signal ls1_on, ls2_on : boolean := false;
begin
  e == v_ref - v_fb;
  i_s == v_s / r_q + c_vs * v_s'dot;

  -- window comparator with deadband and hysteresis, and the direction logic
  direction : process (e'above(deadband + hysteresis), e'above(deadband),
                       e'above(-deadband), e'above(-deadband - hysteresis))
  begin
    if e'above(deadband + hysteresis) then
      up <= true;
    elsif not e'above(deadband) then
      up <= false;
    end if;
    if not e'above(-deadband - hysteresis) then
      down <= true;
    elsif e'above(-deadband) then
      down <= false;
    end if;
  end process direction;

  -- overvoltage lockout with hysteresis
  overvoltage : process (v_s'above(ovhi_off), v_s'above(ovlo_off))
  begin
    if v_s'above(ovhi_off) then
      ov_state <= true;
    elsif not v_s'above(ovlo_off) then
      ov_state <= false;
    end if;
  end process overvoltage;

  ov <= ov_state;

  -- switch states: up = out1 high, out2 low; down = the reverse;
  -- neither = brake (both high sides on); ov = all off
  hs1_on <= not ov_state and not down;
  ls1_on <= not ov_state and down;
  hs2_on <= not ov_state and not up;
  ls2_on <= not ov_state and up;

  break on hs1_on, ls1_on, hs2_on, ls2_on;

  if hs1_on use i_hs1 == v_hs1 / r_on_hs; else i_hs1 == v_hs1 / r_off; end use;
  if ls1_on use i_ls1 == v_ls1 / r_on_ls; else i_ls1 == v_ls1 / r_off; end use;
  if hs2_on use i_hs2 == v_hs2 / r_on_hs; else i_hs2 == v_hs2 / r_off; end use;
  if ls2_on use i_ls2 == v_ls2 / r_on_ls; else i_ls2 == v_ls2 / r_off; end use;

  -- clamp (freewheeling) diodes: each output to vs and from gnd
  clamp_hs1 : entity work.diode(behavioral)
    generic map (is_sat => is_clamp_hs, rs => rs_clamp)
    port map (anode => out1, cathode => vs);
  clamp_ls1 : entity work.diode(behavioral)
    generic map (is_sat => is_clamp_ls, rs => rs_clamp)
    port map (anode => gnd, cathode => out1);
  clamp_hs2 : entity work.diode(behavioral)
    generic map (is_sat => is_clamp_hs, rs => rs_clamp)
    port map (anode => out2, cathode => vs);
  clamp_ls2 : entity work.diode(behavioral)
    generic map (is_sat => is_clamp_ls, rs => rs_clamp)
    port map (anode => gnd, cathode => out2);
end architecture behavioral;
