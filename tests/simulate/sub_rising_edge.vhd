-- std_logic_1164 through its VHDL bodies: rising_edge, to_x01 and the logic operators.
library ieee;
use ieee.std_logic_1164.all;

entity sub_rising_edge is
end entity sub_rising_edge;

architecture test of sub_rising_edge is
  signal clk : std_logic := '0';
  signal count : integer := 0;
begin
  clk <= not clk after 5 ns when now < 100 ns else clk;

  process (clk)
  begin
    if rising_edge(clk) then
      count <= count + 1;
      report "edge";
    end if;
  end process;

  process
    variable a, b : std_logic;
  begin
    a := '1';
    b := 'H';
    assert (a and b) = '1' report "1 and H" severity failure;
    assert (a and 'L') = '0' report "1 and L" severity failure;
    assert (std_ulogic'('U') and '0') = '0' report "U and 0" severity failure;
    assert (std_ulogic'('U') or '1') = '1' report "U or 1" severity failure;
    assert (std_ulogic'('Z') or '0') = 'X' report "Z or 0" severity failure;
    assert (a xor b) = '0' report "1 xor H" severity failure;
    assert (a nand b) = '0' report "1 nand H" severity failure;
    assert (not std_ulogic'('L')) = '1' report "not L" severity failure;
    assert to_x01(b) = '1' and to_x01(std_ulogic'('Z')) = 'X' report "to_x01" severity failure;
    assert to_bit(b) = '1' report "to_bit" severity failure;
    report "logic ok";
    wait;
  end process;
end architecture test;
