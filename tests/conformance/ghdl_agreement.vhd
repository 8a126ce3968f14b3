-- vams: stop 100 ns
--
-- Disagreements with GHDL that the differential test (tests/it/ghdl_differential.rs) found,
-- reduced to their cause; each testbench checks the LRM's answer, which GHDL 2.0 gives.

-- The logical operators and `not` on static arrays (qualified literals), folded at
-- elaboration as the kernel computes them at run time.
entity tb_ghdl_static_array_logic is end;
architecture t of tb_ghdl_static_array_logic is
  subtype bv4 is bit_vector(3 downto 0);
begin
  process
    variable x : bv4;
  begin
    x := bv4'("1101") and bv4'("0011");
    assert x = "0001" report "static and" severity error;
    assert (not bv4'("0010")) = "1101" report "static not" severity error;
    assert not ((not bv4'("0010")) < bv4'("0100")) report "static not in a comparison" severity error;
    -- (GHDL 2.0 stops with an internal error on this one, folding `xnor` of two literals.)
    assert (bv4'("1100") xnor bv4'("1010")) = "1001" report "static xnor" severity error;
    wait;
  end process;
end;

-- A character of a string variable as an assignment target (`r(k) := '1'`), in a function and
-- in a process.
entity tb_ghdl_string_elements is end;
architecture t of tb_ghdl_string_elements is
  function img(v : bit_vector) return string is
    variable r : string(1 to v'length);
    variable k : integer := 1;
  begin
    for i in v'range loop
      if v(i) = '1' then
        r(k) := '1';
      else
        r(k) := '0';
      end if;
      k := k + 1;
    end loop;
    return r;
  end function img;
begin
  process
    variable s : string(1 to 3) := "abc";
  begin
    assert img(bit_vector'("0110")) = "0110" report "img" severity error;
    s(2) := 'x';
    assert s = "axc" report "s(2) := 'x'" severity error;
    wait;
  end process;
end;

-- Inertial pulse rejection on a composite signal works scalar subelement by scalar subelement
-- (LRM 12.6.1 gives each one its own driver; 12.6.2 marks their transactions one by one). The
-- transaction of "1100" at 8 ns lies in the rejection interval of the assignment of "1110" at
-- 12 ns: it is kept for the elements where both values agree (3, 2 and 0) and rejected for
-- element 1 alone, so at 8 ns the vector becomes 1100 (comparing whole values, it would be
-- dropped and the vector would stay 1000 until 12 ns).
entity tb_ghdl_composite_inertial is end;
architecture t of tb_ghdl_composite_inertial is
  signal v : bit_vector(3 downto 0) := "1000";
  signal w : bit_vector(0 to 2) := "000";
begin
  stimulus : process
  begin
    v <= inertial "1100" after 4 ns;
    w <= inertial "110" after 4 ns;
    wait for 2 ns;
    v <= inertial "1110" after 10 ns;
    w <= inertial "001" after 10 ns;
    wait;
  end process;
  check : process
  begin
    wait for 5 ns;
    assert v = "1100" report "v at 5 ns: the agreeing elements' transaction is kept" severity error;
    -- No element of w agrees: the whole transaction goes.
    assert w = "000" report "w at 5 ns: the transaction is rejected" severity error;
    wait for 8 ns;
    assert v = "1110" report "v at 13 ns" severity error;
    assert w = "001" report "w at 13 ns" severity error;
    wait;
  end process;
end;

-- The pulse-rejection interval of an inertial assignment starts at the first new element's
-- time minus the limit, here now: a zero-delay transaction pending at 1.7 ns is inside it and,
-- of another value, rejected. (In floating point, 1.7 ns + 4.6 ns - 4.6 ns is a little after
-- 1.7 ns, which kept the transaction.)
entity tb_ghdl_inertial_window is end;
architecture t of tb_ghdl_inertial_window is
  signal s, r : bit := '0';
begin
  process
  begin
    wait for 1.7 ns;
    s <= '1';
    s <= '0' after 4.6 ns;
    r <= '1';
    r <= reject 4.6 ns inertial '0' after 4.6 ns;
    wait for 0 ns;
    assert s = '0' report "s: the zero-delay transaction is rejected" severity error;
    assert r = '0' report "r: the zero-delay transaction is rejected" severity error;
    wait;
  end process;
end;

-- A zero-delay transport assignment to a resolved signal with two drivers changes it in the
-- next delta cycle (LRM 12.6.2: the signal is active, its resolution function is called on
-- its drivers' values, '1' and 'Z'). GHDL 2.0 misses this: it keeps 'Z' until another driver
-- changes, a GHDL bug that the generator avoids (zero-delay transport only on signals with
-- one driver).
library ieee;
use ieee.std_logic_1164.all;
entity tb_ghdl_transport_resolved is end;
architecture t of tb_ghdl_transport_resolved is
  signal s : std_logic := 'Z';
begin
  first : process
  begin
    s <= transport '1';
    wait;
  end process;
  second : process
  begin
    s <= '0' after 2 ns;
    wait for 1 ns;
    assert s = '1' report "s at 1 ns: resolved('1', 'Z')" severity error;
    wait for 2 ns;
    assert s = 'X' report "s at 3 ns: resolved('1', '0')" severity error;
    wait;
  end process;
end;

-- A qualified expression of a constrained array subtype has that subtype's length, also where
-- the operand's length is known only at run time (a concatenation with a function result):
-- `to_stdlogicvector`'s local arrays are sized by it.
library ieee;
use ieee.std_logic_1164.all;
entity tb_ghdl_qualified_length is end;
architecture t of tb_ghdl_qualified_length is
  subtype bv4 is bit_vector(3 downto 0);
  function low(v : bv4) return bit_vector is
  begin
    return v(1 downto 0);
  end function low;
  signal s : bv4 := "0110";
begin
  process
    variable x : std_logic_vector(3 downto 0);
  begin
    x := to_stdlogicvector(bv4'(s(0) & s(1) & low(s)));
    assert x = "0110" report "to_stdlogicvector of a qualified concatenation" severity error;
    wait;
  end process;
end;

-- Implicit sensitivity takes the longest static prefix of each name (LRM 8.1): `s(1)` read
-- with a constant index waits on that element, so an event on `s(0)` alone does not resume
-- `wait until s(1) and s(2)` although the condition is already true (seed 3524 of the
-- differential test). Likewise for a process with `all` and a concurrent statement.
entity tb_ghdl_element_sensitivity is end;
architecture t of tb_ghdl_element_sensitivity is
  type bool_arr is array (0 to 2) of boolean;
  signal s : bool_arr := (false, true, true);
  signal wakes, concurrent_runs : natural := 0;
  signal copy : boolean;
begin
  s <= (true, true, true) after 5 ns, (true, false, true) after 8 ns,
       (true, true, true) after 11 ns;
  waiter : process
  begin
    wait until s(1) and s(2);
    wakes <= wakes + 1;
    assert now = 11 ns report "woke at " & time'image(now) & ", not when s(1) rose"
      severity error;
  end process;
  copy <= s(1);
  count : process (copy) is
  begin
    if now > 0 ns then
      concurrent_runs <= concurrent_runs + 1;
    end if;
  end process;
  check : process
  begin
    wait for 20 ns;
    assert wakes = 1 report "the wait resumed " & integer'image(wakes) & " times, not once"
      severity error;
    assert concurrent_runs = 2 report "copy changed " & integer'image(concurrent_runs) & " times"
      severity error;
    wait;
  end process;
end;
