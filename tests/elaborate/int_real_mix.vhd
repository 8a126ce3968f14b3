entity t is
  generic (gain : real := 2.0);
end;
architecture a of t is
  quantity x : real;
begin
  x == gain * 3;
end;
