-- vams: stop 200 ns
--
-- Signal parameters associated element by element (Ashenden's zmux testbench:
-- `all_possible_values(bv(0) => sel0, bv(1) => sel1, ..., delay_between_values => 10 ns)`):
-- an `out` parameter drives the signals it gathers, an `in` parameter reads them and waits on
-- their events; the parameter's range is the formals' indexes.

entity tb_signal_parameter_elements is
end entity tb_signal_parameter_elements;

architecture test of tb_signal_parameter_elements is

  -- Counts through every value of bv, MSB at the left, one value per interval.
  procedure count_through ( signal bv : out bit_vector; interval : in delay_length ) is
    variable value : bit_vector(bv'range) := (others => '0');
  begin
    for step in 0 to 2 ** bv'length - 1 loop
      bv <= value;
      wait for interval;
      for k in bv'reverse_range loop   -- increment
        value(k) := not value(k);
        exit when value(k) = '1';
      end loop;
    end loop;
    wait;
  end procedure count_through;

  -- Waits for the next event on v and returns the number of '1' elements.
  procedure ones_after_event ( signal v : in bit_vector; count : out natural;
                               width : out natural ) is
    variable n : natural := 0;
  begin
    wait on v;
    for k in v'range loop
      if v(k) = '1' then
        n := n + 1;
      end if;
    end loop;
    count := n;
    width := v'length;
  end procedure ones_after_event;

  signal hi, mid : bit;
  signal low_pair : bit_vector(1 downto 0);
  signal seen : natural := 0;

begin

  stimulus : count_through ( bv(0) => hi, bv(1) => mid, bv(2 to 3) => low_pair,
                             interval => 10 ns );

  observe : process is
    variable count, width : natural;
  begin
    ones_after_event ( v(5) => hi, v(6) => mid, v(7) => low_pair(1), v(8) => low_pair(0),
                       count => count, width => width );
    assert width = 4 report "v'length = " & integer'image(width) severity error;
    -- At 10 ns * k the value is k.
    assert (now / 10 ns) mod 16 > 0 report "an event at " & time'image(now) severity error;
    seen <= seen + 1;
    wait for 0 ns;
  end process observe;

  check : process is
  begin
    wait for 55 ns;                     -- value 5 = 0101
    assert hi = '0' and mid = '1' and low_pair = "01"
      report "at 55 ns: " & bit'image(hi) & bit'image(mid) severity error;
    wait for 100 ns;                    -- value 15 = 1111
    assert hi = '1' and mid = '1' and low_pair = "11"
      report "at 155 ns" severity error;
    -- One event at each of 10, 20, ..., 150 ns.
    assert seen = 15 report "events seen: " & integer'image(seen) severity error;
    wait;
  end process check;

end architecture test;
