-- 'simple_name, 'path_name and 'instance_name (LRM 14.1) of a signal inside an instance, of
-- a process variable and of the process, as Ashenden's chapter on attributes prints them.
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
    assert level'instance_name = ":tb_name_attributes(test):u1@name_leaf(a):level"
      report level'instance_name severity error;
    wait;
  end process;
end architecture a;

entity tb_name_attributes is
end entity tb_name_attributes;

architecture test of tb_name_attributes is
begin
  u1 : entity work.name_leaf;

  stimulus : process is
    variable var : bit;
  begin
    assert tb_name_attributes'path_name = ":tb_name_attributes:"
      report tb_name_attributes'path_name severity error;
    assert stimulus'path_name = ":tb_name_attributes:stimulus:"
      report stimulus'path_name severity error;
    assert var'path_name = ":tb_name_attributes:stimulus:var"
      report var'path_name severity error;
    assert var'instance_name = ":tb_name_attributes(test):stimulus:var"
      report var'instance_name severity error;
    wait;
  end process stimulus;
end architecture test;
