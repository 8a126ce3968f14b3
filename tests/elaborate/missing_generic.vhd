entity leaf is
  generic (r : real);
end;
architecture a of leaf is
begin
end;

entity t is end;
architecture a of t is
begin
  u1 : entity work.leaf;
end;
