-- A voltage source written as an across quantity alone: no through quantity can balance it,
-- so the model has one equation too many; the diagnostic points at the source's equation.
library ieee;
use ieee.electrical_systems.all;

entity across_only_source is
end entity across_only_source;

architecture a of across_only_source is
  terminal t1 : electrical;
  quantity vr across ir through t1;
  quantity vs across t1;
begin
  resistor : vr == ir * 10.0;
  source : vs == 5.0;
end architecture a;
