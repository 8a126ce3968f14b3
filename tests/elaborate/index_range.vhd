library ieee;
use ieee.electrical_systems.all;

entity t is
  generic (n : positive := 4);
end entity t;

architecture a of t is
  terminal node : electrical_vector(0 to n);
  quantity v across i through node(0) to electrical_ref;
begin
  v == 1.0;
  g : for k in 1 to n generate
    quantity vk across ik through node(k) to node(k + 1);
  begin
    vk == 1.0e3 * ik;
  end generate g;
end architecture a;
