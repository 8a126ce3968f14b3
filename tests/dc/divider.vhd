-- divider: n + 1 equal resistors in series from 1 V; vout is the voltage over the last one,
-- 1/(n + 1). An integer generic: `vams dc --sweep n 1 5 1` elaborates a chain of n sections.
-- vams: stop 1 ms
library ieee;
use ieee.electrical_systems.all;
entity tb_divider is
  generic (n : positive := 2; r : real := 1.0e3);
end entity;
architecture bench of tb_divider is
  terminal nodes : electrical_vector(0 to n);
  quantity vs across is_src through nodes(0) to electrical_ref;
  quantity vout across nodes(n) to electrical_ref;
begin
  vs == 1.0;
  chain : for k in 0 to n - 1 generate
    quantity v across i through nodes(k) to nodes(k + 1);
  begin
    v == r * i;
  end generate;
  last : block
    quantity v across i through nodes(n) to electrical_ref;
  begin
    v == r * i;
  end block;
end architecture;
