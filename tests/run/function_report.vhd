-- A function that reports (a note, and a failed assertion of severity warning) while a
-- process evaluates it: the reports print in order with the process's own, located at the
-- function's statements, and the run goes on.
entity function_report is
end entity function_report;

architecture test of function_report is
  function checked_half (x : integer) return integer is
  begin
    report "halving " & integer'image(x);
    assert x mod 2 = 0 report "odd value" severity warning;
    return x / 2;
  end function checked_half;
begin
  process
  begin
    report "half of 7 is " & integer'image(checked_half(7));
    wait for 1 ms;
    report "done";
    wait;
  end process;
end architecture test;
