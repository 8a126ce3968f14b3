-- User-defined functions: a recursive factorial in a package (declared in the package, body
-- in the package body), overloads by argument type, named association and defaults, and a
-- function declared in a process.
package sub_math is
  function factorial (n : integer) return integer;
  function half (x : real) return real;
  function half (n : integer) return integer;
  function scaled (x : real; gain : real := 10.0; offset : real := 0.0) return real;
end package sub_math;

package body sub_math is
  function factorial (n : integer) return integer is
  begin
    if n <= 1 then
      return 1;
    end if;
    return n * factorial(n - 1);
  end function factorial;

  function half (x : real) return real is
  begin
    return x / 2.0;
  end function half;

  function half (n : integer) return integer is
  begin
    return n / 2;
  end function half;

  function scaled (x : real; gain : real := 10.0; offset : real := 0.0) return real is
    constant g : real := gain;
    variable y : real := x * g;
  begin
    y := y + offset;
    return y;
  end function scaled;
end package body sub_math;

use work.sub_math.all;

entity sub_functions is
end entity sub_functions;

architecture test of sub_functions is
  -- An architecture's function that reads a signal of the architecture.
  signal level : integer := 3;
  impure function level_squared return integer is
  begin
    return level * level;
  end function level_squared;
begin
  process
    function sum_to (n : integer) return integer is
      variable s : integer := 0;
    begin
      for i in 1 to n loop
        s := s + i;
      end loop;
      return s;
    end function sum_to;
  begin
    assert factorial(10) = 3628800 report "factorial(10) wrong" severity failure;
    assert factorial(0) = 1 report "factorial(0) wrong" severity failure;
    assert half(7) = 3 report "integer half wrong" severity failure;
    assert half(7.0) = 3.5 report "real half wrong" severity failure;
    assert scaled(2.0) = 20.0 report "defaults wrong" severity failure;
    assert scaled(2.0, offset => 1.0) = 21.0 report "named default wrong" severity failure;
    assert scaled(offset => 1.0, gain => 3.0, x => 2.0) = 7.0 report "named wrong" severity failure;
    assert sum_to(100) = 5050 report "sum_to wrong" severity failure;
    assert level_squared = 9 report "level_squared wrong" severity failure;
    report "functions ok";
    wait;
  end process;
end architecture test;
