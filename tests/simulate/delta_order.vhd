-- Delta cycles: b follows a one delta later, c two; all at the same simulation time.
entity delta_order is
end entity delta_order;

architecture test of delta_order is
  signal a, b, c : integer := 0;
begin
  b <= a;
  c <= b;
  stim : process
  begin
    a <= 1;
    wait for 0 ns;
    assert a = 1 and b = 0 and c = 0 report "delta 1: a b c wrong" severity failure;
    wait for 0 ns;
    assert b = 1 and c = 0 report "delta 2: b c wrong" severity failure;
    wait for 0 ns;
    assert c = 1 report "delta 3: c wrong" severity failure;
    assert now = 0 ns report "time advanced" severity failure;
    report "done";
    wait;
  end process stim;
end architecture test;
