entity e is end;
architecture a of e is
  quantity across : real;
begin
end architecture a;
