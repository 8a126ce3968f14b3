-- S'delayed(T): a signal that follows S by a transport delay (LRM 14.1), and S'delayed
-- (one delta cycle) in a setup check; S'stable and S'stable(T) as values.
-- vams: stop 100 ns

entity tb_delayed_signals is
end entity tb_delayed_signals;

architecture test of tb_delayed_signals is
  signal clk, d : bit := '0';
  signal late : bit;
begin
  clk <= '1' after 20 ns, '0' after 40 ns, '1' after 60 ns;
  d <= '1' after 10 ns, '0' after 55 ns;
  late <= d'delayed(5 ns);

  check : process is
  begin
    wait for 12 ns;
    assert d = '1' and d'delayed(5 ns) = '0' and late = '0';
    wait for 4 ns;   -- 16 ns
    assert late = '1' and d'delayed(5 ns) = '1';
    assert d'stable and d'stable(5 ns) and not d'stable(7 ns);
    wait;
  end process check;

  -- The value d had before the clock edge's delta cycle: a setup check.
  setup : process (clk) is
  begin
    if clk = '1' then
      assert not clk'stable report "clk'stable is false in the cycle of its event";
      assert d'delayed = d report "d changed in the clock's delta cycle";
      assert d'stable(5 ns) report "d changed within 5 ns of the clock";
      if now = 60 ns then
        assert d = '0' and d'delayed(10 ns) = '1' report "d'delayed(10 ns) at 60 ns";
      end if;
    end if;
  end process setup;
end architecture test;
