entity t is end;
architecture a of t is
  signal s : real := 0.0;
  quantity y : real;
begin
  y == s'driving_value;
end;
