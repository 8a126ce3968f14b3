-- A PWL source whose table's times go backwards (a typo: 2.0e-3 for 0.2e-3).
library ieee;
use ieee.electrical_systems.all;
library vams;
use vams.tables.all;

entity bad_table is
end entity bad_table;

architecture a of bad_table is
  terminal n : electrical;
  quantity v across i through n to electrical_ref;
begin
  v == pwl((0.0, 0.0, 2.0e-3, 5.0, 1.0e-3, 5.0), now);
  i == v / 1.0e3;
end architecture a;
