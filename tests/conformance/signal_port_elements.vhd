-- vams: stop 100 ns
--
-- Signal ports associated element by element (Ashenden, chapter 5: `port map (i(1) =>
-- serial_select, i(2) => write_en, i(3) => bus_clk, ...)`): an unconstrained `in` port takes
-- the formals' indexes as its range, its events are its elements'; an `out` port drives the
-- signals, elements of arrays and slices it is associated with.

entity and_reduce is
  port ( i : in bit_vector;  y : out bit;  width : out integer );
end entity and_reduce;

architecture behavioral of and_reduce is
begin
  reducer : process (i) is
    variable result : bit;
  begin
    result := '1';
    for index in i'range loop
      result := result and i(index);
    end loop;
    y <= result after 2 ns;
    width <= i'length;
  end process reducer;
end architecture behavioral;

entity splitter is
  port ( o : out bit_vector(0 to 3) );
end entity splitter;

architecture behavioral of splitter is
begin
  drive : process is
  begin
    o <= "1011";
    wait for 20 ns;
    o(2) <= '0';
    wait for 20 ns;
    o <= "0100";
    wait;
  end process drive;
end architecture behavioral;

entity tb_signal_port_elements is
end entity tb_signal_port_elements;

architecture test of tb_signal_port_elements is
  signal a, b, c, y : bit;
  signal width : integer;
  signal s0, s3 : bit;
  signal pair : bit_vector(1 to 2);
  signal wide : bit_vector(7 downto 0);
begin
  gate : entity work.and_reduce
    port map ( i(1) => a, i(2) => b, i(3) => c, y => y, width => width );

  split : entity work.splitter
    port map ( o(0) => s0, o(1 to 2) => pair, o(3) => wide(5) );

  stimulus : process is
  begin
    a <= '1';  b <= '1';
    wait for 10 ns;
    c <= '1';
    wait for 10 ns;
    b <= '0';
    wait;
  end process stimulus;

  check : process is
  begin
    wait for 1 ns;
    assert width = 3 report "i'length = " & integer'image(width) severity error;
    assert y = '0' report "y at 1 ns = " & bit'image(y) severity error;
    assert s0 = '1' and pair = "01" and wide = "00100000"
      report "splitter at 1 ns" severity error;
    wait for 12 ns;                     -- 13 ns: c rose at 10 ns, y at 12 ns
    assert y = '1' report "y at 13 ns = " & bit'image(y) severity error;
    wait for 10 ns;                     -- 23 ns: b fell at 20 ns, y at 22 ns
    assert y = '0' report "y at 23 ns = " & bit'image(y) severity error;
    assert pair = "00" and s0 = '1' and wide(5) = '1'
      report "splitter at 23 ns: o(2) cleared" severity error;
    wait for 20 ns;                     -- 43 ns: o = "0100"
    assert s0 = '0' and pair = "10" and wide = "00000000"
      report "splitter at 43 ns" severity error;
    assert y'last_event = 21 ns
      report "y'last_event = " & time'image(y'last_event) severity error;
    wait;
  end process check;
end architecture test;
