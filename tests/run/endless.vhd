-- endless: a driven first-order system with no end in sight (run with a huge --stop), for
-- stopping a run with Ctrl-C.

library ieee;
use ieee.math_real.all;

entity endless is
end entity endless;

architecture a of endless is
  quantity x : real;
begin
  x'dot == -x + sin(2.0 * math_pi * now);
end architecture a;
