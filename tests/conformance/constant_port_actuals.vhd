-- An `in` port associated with a static expression (a literal, a constant, an aggregate):
-- the port is a signal of that value (LRM 1.1.1.2).
-- vams: stop 20 ns

entity enabled_and is
  port (a, b : in bit; en : in boolean; y : out bit);
end entity enabled_and;

architecture behav of enabled_and is
begin
  y <= a and b when en else '0';
end architecture behav;

entity tb_constant_port_actuals is
end entity tb_constant_port_actuals;

architecture test of tb_constant_port_actuals is
  constant enabled : boolean := true;
  signal x, y1, y2 : bit := '0';
begin
  g1 : entity work.enabled_and port map (a => x, b => '1', en => enabled, y => y1);
  g2 : entity work.enabled_and port map (a => x, b => '0', en => not enabled, y => y2);
  x <= '1' after 5 ns;

  process is
  begin
    wait for 10 ns;
    assert y1 = '1' report "x and '1'";
    assert y2 = '0';
    wait;
  end process;
end architecture test;
