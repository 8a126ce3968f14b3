-- vams: stop 1 ns
--
-- A package body with a context clause of its own, naming a library its declaration does
-- not (the book's `bit_vector_signed_arithmetic`: `library ieee; use ieee.numeric_bit.all;`
-- just before the body).

package rounding is
  function half_up (x : integer) return integer;
end package rounding;

library ieee;
use ieee.math_real.all;

package body rounding is
  function half_up (x : integer) return integer is
  begin
    return integer(ceil(real(x) / 2.0));
  end function half_up;
end package body rounding;

use work.rounding.all;

entity tb_package_body_context is
end entity tb_package_body_context;

architecture test of tb_package_body_context is
begin
  process
  begin
    assert half_up(5) = 3 report "half_up(5) = " & integer'image(half_up(5)) severity error;
    assert half_up(-5) = -2 report "half_up(-5) = " & integer'image(half_up(-5)) severity error;
    wait;
  end process;
end architecture test;
