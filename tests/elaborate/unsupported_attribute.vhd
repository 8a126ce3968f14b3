entity t is end;
architecture a of t is
  quantity x, y : real;
begin
  y == x'ltf((0 => 1.0), (0 => 1.0, 1 => 1.0e-3));
  x == 1.0;
end;
