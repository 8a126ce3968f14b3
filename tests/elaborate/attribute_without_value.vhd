-- A user-defined attribute read of an entity that no attribute specification decorates.
entity t is
end entity t;

architecture test of t is
  signal clk, data : bit;
  attribute max_wire_delay : delay_length;
  attribute max_wire_delay of clk : signal is 50 ps;
begin
  process
  begin
    report time'image(data'max_wire_delay);
    wait;
  end process;
end architecture test;
