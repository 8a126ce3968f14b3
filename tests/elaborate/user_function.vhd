entity t is end;
architecture a of t is
  function clipped (v : real) return real is
  begin
    if v > 1.0 then
      return 1.0;
    end if;
    return v;
  end function;
  quantity x : real;
begin
  x == clipped(2.0);
end;
