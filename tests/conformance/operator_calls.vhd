-- vams: stop 1 ns
--
-- Operators called as functions, by their operator symbol and by expanded name, the way
-- the book's address decoder and limit checker write them: `work.cpu_types."="(a, b)` and
-- `std.standard."<"(l, r)` name the predefined operators of a type, `"+"(a, b)` the visible
-- one, and a user function that overloads an operator still wins where it is named.

package cpu_types is
  type status_value is (halted, fetch, mem_read, mem_write, io_read, io_write);
  type word is range 0 to 255;
  function "+" (l, r : word) return word;
end package cpu_types;

package body cpu_types is
  -- Wraps around instead of overflowing: distinguishes the user's "+" from the predefined.
  function "+" (l, r : word) return word is
  begin
    return word((integer(l) + integer(r)) mod 256);
  end function "+";
end package body cpu_types;

entity tb_operator_calls is
end entity tb_operator_calls;

architecture test of tb_operator_calls is

  -- Signed comparison of two's-complement bit vectors, by inverting the sign bits and
  -- calling the predefined ordering of bit_vector.
  function "<" (l, r : bit_vector) return boolean is
    variable tmp1 : bit_vector(l'range) := l;
    variable tmp2 : bit_vector(r'range) := r;
  begin
    tmp1(tmp1'left) := not tmp1(tmp1'left);
    tmp2(tmp2'left) := not tmp2(tmp2'left);
    return std.standard."<"(tmp1, tmp2);
  end function "<";

  signal status : work.cpu_types.status_value := work.cpu_types.mem_read;

begin

  process
    variable w : work.cpu_types.word := 200;
  begin
    assert work.cpu_types."="(status, work.cpu_types.mem_read)
      or work.cpu_types."="(status, work.cpu_types.mem_write)
      report "expanded-name equality" severity error;
    assert not work.cpu_types."="(status, work.cpu_types.fetch)
      report "expanded-name inequality" severity error;
    assert "<"(bit_vector'("1000"), bit_vector'("0111"))
      report "user ordering: -8 < 7" severity error;
    assert not std.standard."<"(bit_vector'("1000"), bit_vector'("0111"))
      report "predefined ordering: 1000 > 0111" severity error;
    assert std.standard."+"(2, 3) = 5 report "predefined +" severity error;
    assert std.standard."-"(4) = -4 report "predefined unary -" severity error;
    -- (No use clause makes word's "=" visible here: it too is named.)
    assert work.cpu_types."="(work.cpu_types."+"(w, 100), 44)
      report "user + by expanded name" severity error;
    wait;
  end process;

end architecture test;
