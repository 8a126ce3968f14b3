-- `write(l, now)` from a VHDL testbench: in VHDL-AMS `now` is both `delay_length` and
-- `real`, so two `write`s fit; the diagnostic says how to qualify it.
use std.textio.all;

entity ambiguous_now is
end entity ambiguous_now;

architecture test of ambiguous_now is
begin
  process
    variable l : line;
  begin
    write(l, now);
    writeline(output, l);
    wait;
  end process;
end architecture test;
