entity leaf is
  generic (gain : real := 1.0);
end;
architecture a of leaf is
begin
end;

entity t is end;
architecture a of t is
begin
  u1 : entity work.leaf generic map (gian => 2.0);
end;
