-- User-defined procedures: out and inout parameters, a procedure that waits (the whole call
-- stack suspends) and one that drives a signal through the calling process's driver.
entity sub_procedures is
end entity sub_procedures;

architecture test of sub_procedures is
  signal pulse_out : bit := '0';
  signal done : boolean := false;

  procedure divmod (a, b : in integer; q : out integer; r : out integer) is
  begin
    q := a / b;
    r := a mod b;
  end procedure divmod;

  procedure accumulate (total : inout real; x : in real := 1.0) is
  begin
    total := total + x;
  end procedure accumulate;

  procedure pause (d : time) is
  begin
    wait for d;
  end procedure pause;

  procedure pulse (signal s : out bit; width : in time) is
  begin
    s <= '1';
    wait for width;
    s <= '0';
  end procedure pulse;
begin
  process
    variable q, r : integer := 0;
    variable total : real := 0.5;
  begin
    divmod(17, 5, q, r);
    assert q = 3 and r = 2 report "divmod wrong" severity failure;
    divmod(b => 4, a => 9, r => r, q => q);
    assert q = 2 and r = 1 report "named divmod wrong" severity failure;
    accumulate(total, 2.0);
    accumulate(total);
    assert total = 3.5 report "accumulate wrong" severity failure;
    report "params ok";
    pause(2 ms);
    report "paused";
    pulse(pulse_out, 3 ms);
    report "pulsed";
    done <= true;
    wait;
  end process;

  -- Observes the pulse from another process.
  process (pulse_out)
  begin
    if pulse_out = '1' then
      report "rise";
    elsif pulse_out'event then
      report "fall";
    end if;
  end process;
end architecture test;
