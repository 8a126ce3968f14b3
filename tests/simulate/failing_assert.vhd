-- An assertion of severity error at 1 ms, then a failure at 2 ms that ends the run.
entity failing_assert is
end entity failing_assert;

architecture test of failing_assert is
begin
  process
  begin
    wait for 1 ms;
    assert false report "first problem" severity error;
    wait for 1 ms;
    assert 1 + 1 = 3 report "arithmetic is broken" severity failure;
    wait for 1 ms;
    report "not reached";
    wait;
  end process;
end architecture test;
