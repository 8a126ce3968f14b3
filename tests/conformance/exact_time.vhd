-- VHDL time is an integer number of femtoseconds (LRM 3.1.3.1): 64 995 waits of 5 us end
-- at exactly 324 975 us, as 4 333 waits of 75 us do, so the two processes' assignments
-- happen at one time point, in one delta cycle. (Sums of seconds in floating point drift
-- 143 fs apart here; a mixed-signal model then met two breakpoints 143 fs apart.)
-- vams: stop 0.33 sec
entity tb_exact_time is
end entity tb_exact_time;

architecture test of tb_exact_time is
  signal a, b : bit := '0';
begin
  fast : process
  begin
    for k in 1 to 64995 loop
      wait for 5 us;
    end loop;
    assert now = 324975 us report "fast ends at " & time'image(now) severity error;
    a <= '1';
    wait;
  end process fast;

  slow : process
  begin
    for k in 1 to 4333 loop
      wait for 75 us;
    end loop;
    assert now = 324975 us report "slow ends at " & time'image(now) severity error;
    b <= '1';
    wait;
  end process slow;

  check : process
  begin
    wait on a, b;
    assert a'event and b'event
      report "a and b changed at different times (a'event " & boolean'image(a'event)
        & ", b'event " & boolean'image(b'event) & ")" severity error;
    assert now = 324975 us report "the events came at " & time'image(now) severity error;
    wait;
  end process check;
end architecture test;
