entity leaf is end;

entity t is end;
architecture a of t is
begin
  u1 : entity work.leaf;
end;
