-- A misspelt quantity name: elaboration reports it with a suggestion.
library ieee;
use ieee.electrical_systems.all;

entity rc is
end entity rc;

architecture a of rc is
  terminal n1 : electrical;
  quantity v across i through n1 to electrical_ref;
  quantity vin : real;
begin
  vin == 1.0;
  i == (vin - v) / 1.0e3 - 1.0e-6 * v'dot;
  vinn == 2.0;
end architecture a;
