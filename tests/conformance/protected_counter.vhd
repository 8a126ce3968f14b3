-- A shared counter of protected type, incremented by two processes and read by a third:
-- every process sees the one object, and its methods keep their private state.
-- vams: stop 100 ns
entity tb_protected_counter is
end entity tb_protected_counter;

architecture test of tb_protected_counter is

  type counter is protected
    procedure increment (by : integer := 1);
    impure function value return integer;
    impure function history (k : natural) return integer;
    procedure reset;
  end protected counter;

  type counter is protected body
    variable count : integer := 0;
    type log_t is array (0 to 7) of integer;
    variable log : log_t := (others => -1);
    variable writes : natural := 0;

    procedure increment (by : integer := 1) is
    begin
      count := count + by;
      log(writes mod 8) := count;
      writes := writes + 1;
    end procedure increment;

    impure function value return integer is
    begin
      return count;
    end function value;

    impure function history (k : natural) return integer is
    begin
      return log(k);
    end function history;

    procedure reset is
    begin
      count := 0;
    end procedure reset;
  end protected body counter;

  shared variable hits, misses : counter;
  signal done_a, done_b : boolean := false;

begin

  a : process
  begin
    for k in 1 to 3 loop
      hits.increment;
      wait for 10 ns;
    end loop;
    done_a <= true;
    wait;
  end process a;

  b : process
  begin
    wait for 5 ns;
    hits.increment(10);
    misses.increment(by => 2);
    done_b <= true;
    wait;
  end process b;

  check : process
  begin
    wait until done_a and done_b;
    assert hits.value = 13 report "hits = " & integer'image(hits.value) severity error;
    assert misses.value = 2 report "misses = " & integer'image(misses.value) severity error;
    -- The order of the increments: 1 at 0 ns, 10 at 5 ns, 1 at 10 ns and 20 ns.
    assert hits.history(0) = 1 and hits.history(1) = 11 and hits.history(2) = 12
      and hits.history(3) = 13 report "history differs" severity error;
    hits.reset;
    assert hits.value = 0 report "reset failed" severity error;
    assert misses.value = 2 report "misses changed with hits" severity error;
    report "protected counter done";
    wait;
  end process check;

end architecture test;
