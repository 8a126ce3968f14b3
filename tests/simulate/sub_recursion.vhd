-- A recursion that never ends: a run-time error naming the process, not a stack overflow.
entity sub_recursion is
end entity sub_recursion;

architecture test of sub_recursion is
  function forever (n : integer) return integer is
  begin
    return forever(n + 1) + 1;
  end function forever;
begin
  runaway : process
    variable x : integer;
  begin
    x := forever(0);
    wait;
  end process runaway;
end architecture test;
