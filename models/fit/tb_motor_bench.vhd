-- tb_motor_bench: the bench of the paper's four motor experiments (PAPER.md section 3), the
-- testbench that `vams extract` fits to the four captures. The motor is `dc_motor` with
-- `constant_friction` on its shaft (the motor's own friction only); it is fed through a
-- switch that closes at `t_on` (closed from the start when `t_on <= 0`) and opens at `t_off`
-- from a supply `vs` behind the source resistance `rs` (supply, wiring, switch), or, when
-- `driven`, from the table `drive` of time (`vams.tables.pwl`): `vams extract` drives each
-- experiment with its capture's own terminal voltage (a blocked rotor at 3 V beside runs at
-- 12 V, a supply that sags during the inrush), less the voltage probe's offset `v_offset`,
-- and compares `v_probe`, what that probe reads, where the voltage is the motor's own (at
-- rest before the switch closes, coasting after it opens).
--   inrush:   t_on = the step's time           current and voltage from rest
--   blocked:  t_on = the step's time, blocked  the rotor held: R and L alone
--   speed:    closed from the start            run up, then the capture at constant speed
--   coast:    closed, t_off = the cut's time   run up, cut, the back-EMF decays to rest
-- An open switch is 1 MOhm: the armature current falls in l/1e6 (nanoseconds), with the
-- inductive kick a real switch gives. Run alone (`vams test models`), it checks itself: with
-- the switch closed from the start the motor reaches the no-load speed of the closed form.
-- vams: stop 300 ms

library ieee;
use ieee.electrical_systems.all;
use ieee.mechanical_systems.all;
library vams;
use vams.tables.all;

entity tb_motor_bench is
  generic (
    r          : real := 8.0;      -- [Ohm] armature resistance
    l          : real := 4.0e-3;   -- [H] armature inductance
    ke         : real := 0.015;    -- [V s/rad] back-EMF constant (= torque constant, SI)
    j          : real := 1.0e-6;   -- [kg m2] rotor inertia
    d          : real := 1.5e-6;   -- [N m s/rad] viscous damping
    tcst_motor : real := 0.3e-3;   -- [N m] the motor's constant friction
    vs         : real := 10.5;     -- [V] supply
    rs         : real := 0.3;      -- [Ohm] source resistance (supply, wiring, switch)
    t_on       : real := 0.0;      -- [s] the switch closes (<= 0: closed from the start)
    t_off      : real := 1.0e9;    -- [s] the switch opens
    blocked    : boolean := false; -- the rotor held
    w_s        : real := 0.5;      -- [rad/s] velocity scale of the friction's smoothing
    driven     : boolean := false; -- the supply is the table `drive`, not `vs`
    drive      : real_vector := (0.0, 0.0); -- [s, V] (t0, v0, t1, v1, ...) when driven
    v_offset   : real := 0.0;      -- [V] the voltage probe's offset (drive and v_probe)
    self_check : boolean := true   -- assert the no-load speed at 290 ms (off while fitting)
  );
end entity tb_motor_bench;

architecture bench of tb_motor_bench is
  terminal supply, p : electrical;
  terminal shaft : rotational_v;
  quantity vsup across isup through supply to electrical_ref;
  quantity vsw across isw through supply to p;
  quantity vm across p to electrical_ref;
  -- What the voltage probe reads.
  quantity v_probe : real;
  quantity speed across shaft to rotational_v_ref;
  -- The rotor's angle since t = 0: `vams extract` reads the commutation ripple's phase from it.
  quantity angle : real;
  signal closed : boolean := t_on <= 0.0;
  constant r_open : real := 1.0e6;
  -- At t = 0 the armature carries what the open switch lets through (the quiescent state
  -- the captures' pre-trigger shows), or nothing when the switch is closed from the start.
  constant i_start : real := real(boolean'pos(t_on > 0.0)) * vs / (r_open + r);
begin
  from_table : if driven generate
    vsup == pwl(drive, now) - v_offset;
  end generate;
  from_vs : if not driven generate
    vsup == vs;
  end generate;
  v_probe == vm + v_offset;
  if closed use
    vsw == rs * isw;
  else
    vsw == r_open * isw;
  end use;
  break on closed;
  angle == speed'integ;

  switch : process
    variable now_s : real := 0.0;
  begin
    if t_on > 0.0 then
      wait for t_on * 1 sec;
      closed <= true;
      now_s := t_on;
    end if;
    if t_off < 1.0e8 then
      wait for (t_off - now_s) * 1 sec;
      closed <= false;
    end if;
    wait;
  end process;

  -- The no-load steady state, friction at full strength (tanh = 1 far above w_s):
  -- vs = (r + rs) i + ke w and ke i = d w + tcst_motor.
  check : process
    constant w_ss : real := (vs - (r + rs) * tcst_motor / ke) / (ke + (r + rs) * d / ke);
  begin
    wait for 290 ms;
    if self_check and t_on <= 0.0 and t_off > 1.0 and not blocked then
      assert abs(speed - w_ss) < 1.0e-3 * w_ss
        report "the run-up ends at " & real'image(speed) & " rad/s, the closed form says "
               & real'image(w_ss)
        severity failure;
    end if;
    wait;
  end process;

  motor : entity work.dc_motor
    generic map (r => r, l => l, kt => ke, ke => ke, d => d, j => j, i0 => i_start)
    port map (p => p, n => electrical_ref, shaft => shaft);

  friction : entity work.constant_friction
    generic map (tcst_motor => tcst_motor, tcst_system => 0.0, w_s => w_s)
    port map (shaft => shaft);

  hold : if blocked generate
    quantity w_held across t_held through shaft to rotational_v_ref;
  begin
    w_held == 0.0;
  end generate;
end architecture bench;
