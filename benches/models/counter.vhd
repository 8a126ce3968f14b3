-- vams: stop 1 ms
--
-- counter: the digital part of counter_rc alone, a counter stepping every 1 ns, in plain
-- VHDL, so that `ghdl -r` runs the same model: the event kernel's time beside GHDL's
-- (issue 23).

entity counter is
end entity counter;

architecture bench of counter is
  signal count : integer := 0;
begin
  count_up : process
  begin
    wait for 1 ns;
    count <= (count + 1) mod 1000000;
  end process count_up;
end architecture bench;
