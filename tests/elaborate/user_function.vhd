entity t is end;
architecture a of t is
  -- How many halvings bring v below 1: the loop's count depends on the operand, so the
  -- function cannot be expanded into an equation.
  function halvings (v : real) return real is
    variable x : real := v;
    variable n : real := 0.0;
  begin
    while x > 1.0 loop
      x := x / 2.0;
      n := n + 1.0;
    end loop;
    return n;
  end function;
  quantity x, y : real;
begin
  x == 1.0e6 * (1.0 + now);
  y == halvings(x);
end;
