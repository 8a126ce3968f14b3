entity t is end;
architecture a of t is
  quantity x, y : real;
begin
  y == x'slew(1.0e3);
  x == 1.0;
end;
