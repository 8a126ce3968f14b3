entity e is end;
architecture a of e is
  quantity x : real;
begin
  x = 1.0;
end architecture a;
