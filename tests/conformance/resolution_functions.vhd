-- Resolution functions of the user's own, guarded signals (`bus`, `register`), guarded
-- assignments that disconnect drivers, `null` transactions, disconnection delays and a
-- `bus` port.
-- vams: stop 200 ns

package wired is
  type bit_array is array (natural range <>) of bit;
  function wired_or (drivers : bit_array) return bit;
  subtype wired_or_bit is wired_or bit;
  type int_array is array (natural range <>) of integer;
  -- The sum of the driving values; -1 with no drivers.
  function sum (drivers : int_array) return integer;
  subtype summed is sum integer;
end package wired;

package body wired is
  function wired_or (drivers : bit_array) return bit is
  begin
    for i in drivers'range loop
      if drivers(i) = '1' then
        return '1';
      end if;
    end loop;
    return '0';
  end function wired_or;

  function sum (drivers : int_array) return integer is
    variable total : integer := 0;
  begin
    if drivers'length = 0 then
      return -1;
    end if;
    for i in drivers'range loop
      total := total + drivers(i);
    end loop;
    return total;
  end function sum;
end package body wired;

use work.wired.all;

entity tri_state_driver is
  port (en : in bit; d : in integer; q : out summed bus);
end entity tri_state_driver;

architecture behav of tri_state_driver is
begin
  process (en, d) is
  begin
    if en = '1' then
      q <= d;
    else
      q <= null;
    end if;
  end process;
end architecture behav;

library ieee;
use ieee.std_logic_1164.all;
use work.wired.all;

entity tb_resolution_functions is
end entity tb_resolution_functions;

architecture test of tb_resolution_functions is
  signal line : wired_or_bit;
  signal b : wired_or_bit bus;
  signal r : wired_or_bit register := '1';
  signal en1, en2 : boolean := false;
  signal total : summed := 0;
  signal sb : std_logic bus;
  signal delayed_bus : summed bus;
  disconnect delayed_bus : summed after 5 ns;
  signal e1, e2 : bit := '0';
  signal shared_bus : summed;
  signal ten : integer := 10;
  signal twenty : integer := 20;
begin
  -- Two unguarded drivers of a wired-or line.
  line <= '0', '1' after 10 ns, '0' after 20 ns;
  line <= '0', '1' after 15 ns, '0' after 30 ns;
  -- Guarded assignments disconnect their drivers while the guard is false.
  drv1 : block (en1) is
  begin
    b <= guarded '1';
    r <= guarded '0';
    sb <= guarded '1';
    delayed_bus <= guarded 7;
  end block;
  drv2 : block (en2) is
  begin
    b <= guarded '0';
    sb <= guarded '0';
  end block;
  -- Three drivers of a summed integer: the function sees every value.
  total <= 1;
  total <= 2;
  total <= 4 after 50 ns;
  -- Two tri-state drivers through `bus` ports.
  u1 : entity work.tri_state_driver port map (en => e1, d => ten, q => shared_bus);
  u2 : entity work.tri_state_driver port map (en => e2, d => twenty, q => shared_bus);

  check : process is
  begin
    -- At initialization every driver holds the signal's initial value, 0.
    assert total = 0 report "initial sum " & integer'image(total);
    wait for 12 ns;
    assert line = '1';
    assert total = 3 report "sum of 1, 2 and 0 (" & integer'image(total) & ")";
    wait for 10 ns;   -- 22 ns
    assert line = '1' report "the second driver is still '1'";
    wait for 10 ns;   -- 32 ns
    assert line = '0';
    assert b = '0' and sb = 'Z' report "a bus with every driver disconnected";
    assert r = '1' report "a register with every driver disconnected keeps its value";
    assert delayed_bus = -1 report "the function of no values";
    assert shared_bus = -1;
    en2 <= true;
    e1 <= '1';
    wait for 1 ns;
    assert b = '0' and sb = '0' report "one driver on the bus";
    assert shared_bus = 10;
    en1 <= true;
    e2 <= '1';
    wait for 1 ns;
    assert b = '1' and r = '0' and sb = 'X' report "both drivers on the bus";
    assert delayed_bus = 7 and shared_bus = 30;
    en1 <= false;
    en2 <= false;
    e1 <= '0';
    wait for 1 ns;
    assert b = '0' and r = '0' and sb = 'Z';
    assert delayed_bus = 7 report "disconnected only after its 5 ns delay";
    assert shared_bus = 20;
    wait for 5 ns;
    assert delayed_bus = -1 report "disconnected after 5 ns";
    wait for 20 ns;
    assert total = 7;
    wait;
  end process;
end architecture test;
