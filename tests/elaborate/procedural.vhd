entity t is end;
architecture a of t is
  quantity x : real;
begin
  procedural is
  begin
    x := 1.0;
  end procedural;
end;
