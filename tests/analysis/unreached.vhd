-- Errors in units no top reaches: a package body nothing calls, and an architecture of an
-- entity whose generic has no default. `vams check` must report both (GHDL does at -a).
package helpers is
  function twice(x : real) return real;
end package helpers;

package body helpers is
  function twice(x : real) return real is
  begin
    return x * 2;                 -- real * integer: no such operator
  end function twice;
end package body helpers;

entity leaf is
  generic (gain : real);
end entity leaf;

architecture rtl of leaf is
  signal s : integer := 1.5;      -- real literal for an integer
begin
end architecture rtl;

entity tb is
end entity tb;

architecture sim of tb is
  signal t : integer := 0;
begin
  t <= 1 after 1 ns;
end architecture sim;
