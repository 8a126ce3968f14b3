entity t is end;
architecture a of t is
  type pair is record
    a, b : real;
  end record;
  constant p : pair := (1.0, 2.0);
  quantity x : real;
begin
  x == 1.0;
end;
