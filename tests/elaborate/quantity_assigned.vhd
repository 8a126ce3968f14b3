entity t is end;
architecture a of t is
  quantity x : real;
  signal go : boolean := false;
begin
  x == 1.0;
  p : process (go)
  begin
    x <= 2.0;
  end process;
end;
