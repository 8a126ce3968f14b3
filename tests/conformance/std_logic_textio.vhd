-- std_logic values and vectors logged and read back with ieee.std_logic_textio.
-- vams: stop 1 ns
library ieee;
use ieee.std_logic_1164.all;
use ieee.std_logic_textio.all;
use std.textio.all;

entity tb_std_logic_textio is
end entity tb_std_logic_textio;

architecture test of tb_std_logic_textio is
begin
  process
    variable l : line;
    variable bit_in : std_ulogic;
    variable word : std_logic_vector(7 downto 0) := "1010ZX01";
    variable back : std_logic_vector(7 downto 0);
    variable hex : std_logic_vector(11 downto 0);
    variable ok : boolean;
  begin
    write(l, word);
    write(l, ' ');
    hwrite(l, std_logic_vector'(X"3C"));
    write(l, ' ');
    write(l, std_ulogic'('H'));
    assert l.all = "1010ZX01 3C H" report "written: " & l.all severity error;
    read(l, back);
    assert back = word report "read back differs" severity error;
    hread(l, hex(7 downto 0), ok);
    assert ok and hex(7 downto 0) = X"3C" report "hread failed" severity error;
    read(l, bit_in);
    assert bit_in = 'H' report "std_ulogic read failed" severity error;
    read(l, bit_in, ok);
    assert not ok report "read past the end succeeded" severity error;
    hwrite(l, word);
    assert l.all = "AX" report "hwrite of metavalues: " & l.all severity error;
    report "std_logic_textio done";
    wait;
  end process;
end architecture test;
