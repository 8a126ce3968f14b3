library ieee;
use ieee.electrical_systems.all;

entity t is end;
architecture a of t is
  quantity v_out : voltage;
begin
  v_out == v_outt * 2.0;
end;
