entity t is end;
architecture a of t is
  quantity x, y : real;
  signal on_state : boolean := false;
begin
  if on_state use
    x == 1.0;
    y == 2.0;
  else
    x == 0.0;
  end use;
end;
