-- vams: stop 1 ns
--
-- A multi-dimensional array nature, as the book declares one (`nature B is array (1 to 10,
-- 19 downto 0) of thermal;`): the nature's attributes give each dimension's bounds.
-- (Terminals of such a nature are not supported yet; vams says so where one is declared.)

library ieee_proposed;
use ieee_proposed.thermal_systems.all;

entity tb_multidimensional_nature is
end entity tb_multidimensional_nature;

architecture test of tb_multidimensional_nature is
  type engine_nodes is (intake, compressor, combustion, exhaust);
  nature B is array (1 to 10, 19 downto 0) of thermal;
  nature engine_flows is array (engine_nodes, 1 to 4) of thermal;
begin
  process
  begin
    assert B'left(1) = 1 and B'right(1) = 10 report "B dimension 1" severity error;
    assert B'left(2) = 19 and B'right(2) = 0 report "B dimension 2" severity error;
    assert B'length(1) = 10 and B'length(2) = 20 report "B lengths" severity error;
    assert B'ascending(1) and not B'ascending(2) report "B directions" severity error;
    assert B'high = 10 and B'low(2) = 0 report "B high and low" severity error;
    assert engine_flows'left(1) = intake and engine_flows'right(1) = exhaust
      report "engine_flows dimension 1" severity error;
    assert engine_flows'length(2) = 4 report "engine_flows dimension 2" severity error;
    wait;
  end process;
end architecture test;
