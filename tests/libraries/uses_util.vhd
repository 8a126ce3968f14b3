-- vams: stop 5 ns
-- A testbench using a resource library (`library util;`), given as `--lib util=DIR`.
library util;
use util.stimulus.all;

entity uses_util is
end entity uses_util;

architecture test of uses_util is
  signal s : bit;
begin
  src : entity util.pulse_source(ideal) port map (s => s);

  check : process is
  begin
    assert doubled(21) = 42 report "doubled" severity failure;
    wait for step + 1 ns;
    assert s = '1' report "the source of library util did not run" severity failure;
    wait;
  end process check;
end architecture test;
