-- The signal attributes 'transaction, 'last_active, 'driving and 'driving_value (LRM 14.1):
-- a transaction without a change toggles 'transaction and resets 'last_active but not
-- 'last_event; 'driving_value is this process's own driver, not the resolved value.
-- vams: stop 100 ns
library ieee;
use ieee.std_logic_1164.all;

entity tb_driver_attributes is
end entity tb_driver_attributes;

architecture test of tb_driver_attributes is
  signal s : integer := 0;
  signal bus_line : std_logic := 'Z';
  signal toggles : natural := 0;
begin
  writer : process
  begin
    s <= 1;
    wait for 10 ns;
    s <= 1;  -- a transaction without an event
    wait for 10 ns;
    s <= 2;
    wait;
  end process writer;

  counter : process (s'transaction)
  begin
    toggles <= toggles + 1;
  end process counter;

  -- Two drivers of a resolved signal: this one drives '1', the other '0'.
  pull_up : process
  begin
    bus_line <= '1';
    wait for 5 ns;
    assert bus_line = 'X' report "resolved value " & std_logic'image(bus_line) severity error;
    assert bus_line'driving_value = '1'
      report "driving_value " & std_logic'image(bus_line'driving_value) severity error;
    assert bus_line'driving report "the driver is connected" severity error;
    wait;
  end process pull_up;

  pull_down : process
  begin
    bus_line <= '0';
    wait;
  end process pull_down;

  check : process
  begin
    wait for 15 ns;
    -- s was active at 10 ns without changing: 5 ns since the transaction, 15 ns since the
    -- event at 0 ns.
    assert s'last_active = 5 ns report "last_active " & time'image(s'last_active) severity error;
    assert s'last_event = 15 ns report "last_event " & time'image(s'last_event) severity error;
    wait for 10 ns;
    -- The counter ran once at initialisation, then once for each of the three
    -- transactions (0, 10 and 20 ns) that toggled s'transaction.
    assert toggles = 4 report "toggles " & integer'image(toggles) severity error;
    report "driver attributes done";
    wait;
  end process check;
end architecture test;
