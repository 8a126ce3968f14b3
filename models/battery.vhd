-- battery: ideal voltage source with a profile of steps and ramps given by
-- generics.
--
-- Conservation (electrical): branch pos -> neg, voltage v across, current i
-- through (any current: ideal source).
-- Profile: v_init at t = 0; segment k (k = 1..4) starts at t_k [s] and moves
-- the voltage linearly to v_k [V] within tr_k [s] (tr_k = 0: a step).  Segments
-- must be in time order and must not overlap; t_k < 0 leaves segment k unused.
-- The profile integrates a slope signal; every slope change and every segment
-- end is a break, and each segment lands exactly on v_k (break v_src => v_k).

library ieee;
use ieee.electrical_systems.all;

entity battery is
  generic (
    v_init : real := 12.0;  -- [V] voltage at t = 0; nominal 12 V vehicle battery
    t1  : real := -1.0;     -- [s] start of segment 1; unused by default (constant battery)
    tr1 : real := 0.0;      -- [s] duration of segment 1's ramp; 0 is a step
    v1  : real := 12.0;     -- [V] voltage at the end of segment 1
    t2  : real := -1.0;     -- [s] as t1, for segment 2
    tr2 : real := 0.0;      -- [s] as tr1, for segment 2
    v2  : real := 12.0;     -- [V] as v1, for segment 2
    t3  : real := -1.0;     -- [s] as t1, for segment 3
    tr3 : real := 0.0;      -- [s] as tr1, for segment 3
    v3  : real := 12.0;     -- [V] as v1, for segment 3
    t4  : real := -1.0;     -- [s] as t1, for segment 4
    tr4 : real := 0.0;      -- [s] as tr1, for segment 4
    v4  : real := 12.0      -- [V] as v1, for segment 4
  );
  port (terminal pos, neg : electrical);
end entity battery;

architecture behavioral of battery is
  type segment_array is array (1 to 4) of real;
  constant t_start : segment_array := (t1, t2, t3, t4);
  constant t_ramp  : segment_array := (tr1, tr2, tr3, tr4);
  constant v_end   : segment_array := (v1, v2, v3, v4);

  quantity v across i through pos to neg;
  quantity v_src : voltage;       -- the profile
  signal slope : real := 0.0;     -- [V/s] d(v_src)/dt of the running segment
begin
  v == v_src;
  v_src'dot == slope;

  break v_src => v_init;          -- initial value
  break on slope;                 -- a slope change is a discontinuity of v_src'dot

  profile : process
    variable v_prev : real := v_init;
  begin
    for k in 1 to 4 loop
      exit when t_start(k) < 0.0;
      wait for t_start(k) * 1 sec - now;
      if t_ramp(k) > 0.0 then
        slope <= (v_end(k) - v_prev) / t_ramp(k);
        wait for t_ramp(k) * 1 sec;
        slope <= 0.0;
      end if;
      break v_src => v_end(k);    -- end of the ramp, or the step itself
      v_prev := v_end(k);
    end loop;
    wait;
  end process profile;
end architecture behavioral;
