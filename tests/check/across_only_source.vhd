-- A voltage source written as an across quantity alone: by the LRM's count it is one
-- equation too many (no through quantity balances it); vams gives the branch an implicit
-- through quantity, as SEAMS did, and warns at the declaration. The conservation law at
-- `n2`, written out as well, is the real error: the terminals already give it.
library ieee;
use ieee.electrical_systems.all;

entity across_only_source is
end entity across_only_source;

architecture a of across_only_source is
  terminal n1, n2 : electrical;
  quantity vr1 across ir1 through n1 to n2;
  quantity vr2 across ir2 through n2;
  quantity vs across n1;
begin
  r1 : vr1 == ir1 * 10.0;
  r2 : vr2 == ir2 * 20.0;
  kcl : ir1 == ir2;
  source : vs == 5.0;
end architecture a;
