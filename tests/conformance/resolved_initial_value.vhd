-- vams: stop 20 ns
--
-- Reduced from the GHDL differential's seeds 3042 and 3608: a `std_logic` signal of default
-- `'-'` with two drivers. Initialisation (LRM 14.7.5.2 b, 1076-2008; 12.6.4 in 1076-2002)
-- sets a resolved signal to its driving value, the resolution function applied to its
-- drivers' initial values (LRM 14.7.3.2): `resolved(('-', '-'))` is 'X' (IEEE 1164's table
-- maps '-' with any value to 'X'; only a single driver's value is returned unresolved). A
-- later transaction `'0'` on one driver gives `resolved(('0', '-'))`, 'X' again: no event.
--
-- GHDL 2.0's mcode backend agrees ('X' at 0 ns, no event) unless some process reads
-- `s'stable` or `s'quiet`; then it leaves the signal at '-' through initialisation and
-- makes an event '-' -> 'X' at 1 ns. Here it prints
--   @0ms:(assertion error): s starts as '-'; expected 'X'
--   @0ms:(assertion error): q starts as '-'; expected 'X'
--   @10ns:(assertion error): s or q changed 1 time(s); expected never
-- and without the process `stable` it passes. `S'stable` and `S'quiet` are signals of
-- their own (LRM 16.2.3) that cannot change the value of `S`: a GHDL defect, so these two
-- disagreements of the differential stay, and this test holds vams to the LRM.

library ieee;
use ieee.std_logic_1164.all;

entity tb_resolved_initial_value is end;
architecture t of tb_resolved_initial_value is
  signal s, q : std_logic := '-';
  signal events : natural := 0;
begin
  a : process
  begin
    assert s = 'X' report "s starts as " & std_logic'image(s) & "; expected 'X'" severity error;
    assert q = 'X' report "q starts as " & std_logic'image(q) & "; expected 'X'" severity error;
    s <= '0' after 1 ns;
    q <= '1' after 1 ns;
    wait for 10 ns;
    assert s = 'X' report "s is " & std_logic'image(s) & "; expected 'X'" severity error;
    assert q = 'X' report "q is " & std_logic'image(q) & "; expected 'X'" severity error;
    assert events = 0
      report "s or q changed " & integer'image(events) & " time(s); expected never"
      severity error;
    wait;
  end process;

  -- The second driver of each, never assigned a transaction.
  b : process
  begin
    if false then
      s <= '1';
      q <= '0';
    end if;
    wait;
  end process;

  watch : process (s, q)
  begin
    if now > 0 ns then
      events <= events + 1;
    end if;
  end process;

  -- Reading the implicit signals is what turns GHDL's answer.
  stable : process
  begin
    wait for 5 ns;
    assert s'stable and q'quiet report "s changed or q was active" severity error;
    wait;
  end process;
end architecture t;
