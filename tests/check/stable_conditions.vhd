-- `S'stable` and `S'quiet` are computed as values: where a process would have to wake when
-- they change, vams says so instead of simulating a process that never wakes.
entity stable_conditions is
end entity stable_conditions;

architecture test of stable_conditions is
  signal clk, d, q, settled : bit;
begin
  -- The old idiom for a clock edge runs (right at the events the statement wakes on).
  q <= d when not clk'stable and clk = '1';

  -- Refused: `settled` would have to change 2 ns after the last event of `d`.
  settled <= '1' when d'stable(2 ns) else '0';

  waiter : process is
  begin
    -- Refused: the process waits on `d` and would never see `d'stable` true.
    wait until d'stable;
    wait;
  end process waiter;
end architecture test;
