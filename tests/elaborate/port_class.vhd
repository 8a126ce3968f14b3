library ieee;
use ieee.electrical_systems.all;

entity leaf is
  port (terminal p : electrical);
end;
architecture a of leaf is
begin
end;

entity t is end;
architecture a of t is
  signal s : boolean;
begin
  u1 : entity work.leaf port map (p => s);
end;
