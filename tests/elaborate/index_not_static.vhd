library ieee;
use ieee.electrical_systems.all;

entity t is
end entity t;

architecture a of t is
  signal which : natural := 1;
  terminal node : electrical_vector(0 to 3);
  quantity v across i through node(which) to electrical_ref;
  quantity q : real_vector(1 to 2);
begin
  v == 1.0;
  q(which) == 0.0;
  q(2) == 1.0;
end architecture a;
