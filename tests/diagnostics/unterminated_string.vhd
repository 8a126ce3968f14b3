entity e is end entity e;
architecture a of e is
  signal s : bit;
begin
  s <= "abc;
end architecture a;
