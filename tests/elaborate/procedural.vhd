entity t is end;
architecture a of t is
  quantity x, y : real;
begin
  y == 1.0e6 * (1.0 + now);
  -- How many halvings bring y below 1: a loop whose count depends on a quantity.
  procedural is
    variable v, n : real := 0.0;
  begin
    v := y;
    while v > 1.0 loop
      v := v / 2.0;
      n := n + 1.0;
    end loop;
    x := n;
  end procedural;
end;
