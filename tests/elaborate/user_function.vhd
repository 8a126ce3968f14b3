entity t is end;
architecture a of t is
  function twice (v : real) return real is
  begin
    return 2.0 * v;
  end function;
  quantity x : real;
begin
  x == twice(1.0);
end;
