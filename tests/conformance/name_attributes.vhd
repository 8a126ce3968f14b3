-- 'simple_name and 'path_name (LRM 14.1) of a signal inside an instance.
-- vams: stop 1 ns
entity name_leaf is
end entity name_leaf;

architecture a of name_leaf is
  signal level : bit;
begin
  process
  begin
    assert level'simple_name = "level" report level'simple_name severity error;
    assert level'path_name = ":tb_name_attributes:u1:level" report level'path_name severity error;
    wait;
  end process;
end architecture a;

entity tb_name_attributes is
end entity tb_name_attributes;

architecture test of tb_name_attributes is
begin
  u1 : entity work.name_leaf;
end architecture test;
