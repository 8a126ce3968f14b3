-- Multi-dimensional arrays and arrays indexed by enumeration types: declarations,
-- nested aggregates, indexing, element targets, attributes of each dimension, loops over
-- enumeration ranges.
-- vams: stop 10 ns

entity tb_multidimensional_arrays is
end entity tb_multidimensional_arrays;

architecture test of tb_multidimensional_arrays is
  type state is (idle, run, stop);
  type symbol is ('a', 'b');
  type transition_matrix is array (state, symbol) of state;
  constant next_state : transition_matrix :=
    ( idle => ('a' => run, 'b' => idle),
      run => ('a' => run, 'b' => stop),
      stop => (others => idle) );
  type matrix is array (1 to 3, 1 to 3) of real;
  constant identity : matrix := ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0));
  type state_counts is array (state range idle to stop) of natural;
  type grid is array (natural range <>, natural range <>) of integer;
  signal counts : state_counts := (others => 0);
  signal current : state := idle;
  type flag_table is array (boolean) of bit;
begin
  process is
    variable m : matrix := (others => (others => 0.0));
    variable g : grid(0 to 1, 0 to 2);
    variable trace : real := 0.0;
    variable n : natural := 0;
    variable s : state := idle;
    variable f : flag_table := (false => '0', true => '1');
  begin
    -- Indexing by enumeration values, and the table read as a state machine.
    assert next_state(idle, 'a') = run and next_state(run, 'b') = stop;
    for c in symbol loop
      assert next_state(stop, c) = idle;
    end loop;
    s := next_state(s, 'a');
    s := next_state(s, 'b');
    assert s = stop;
    -- Element targets, and nested loops over both dimensions' ranges.
    for i in m'range(1) loop
      for j in m'range(2) loop
        m(i, j) := identity(i, j) * real(i + j);
      end loop;
    end loop;
    for i in 1 to 3 loop
      trace := trace + m(i, i);
    end loop;
    assert trace = 12.0 report "trace " & real'image(trace);
    assert m(1, 2) = 0.0 and m(3, 3) = 6.0;
    assert m'length(1) = 3 and m'length(2) = 3 and m'left(2) = 1 and m'high(1) = 3;
    g := ((1, 2, 3), (4, 5, 6));
    assert g(1, 0) = 4 and g(0, 2) = 3 and g'length(2) = 3 and g'right(1) = 1;
    g(1, 2) := 60;
    assert g = ((1, 2, 3), (4, 5, 60));
    -- Attributes of an enumeration-indexed array are enumeration values.
    assert counts'left = idle and counts'right = stop and counts'length = 3;
    for st in counts'range loop
      n := n + 1;
    end loop;
    assert n = 3;
    for st in state loop
      counts(st) <= counts(st) + state'pos(st) + 1;
    end loop;
    assert f(true) = '1' and f(false) = '0';
    wait for 1 ns;
    assert counts = (1, 2, 3) report "counts";
    assert counts(run) = 2;
    wait;
  end process;
end architecture test;
