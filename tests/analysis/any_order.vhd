-- Every secondary unit before its primary and a user before the package it uses: analysis
-- takes them in dependency order, not file order. No errors.
architecture a of user is
  signal s : real := scale * 2.0;
begin
  s <= double(s) after 1 ns;
end architecture a;

package body numbers is
  function double(x : real) return real is
  begin
    return x * 2.0;
  end function double;
end package body numbers;

use work.numbers.all;
entity user is
end entity user;

package numbers is
  constant scale : real := 1.5;
  function double(x : real) return real;
end package numbers;
