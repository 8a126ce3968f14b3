library ieee;
use ieee.electrical_systems.all;

entity pair_user is
  port (terminal t : electrical_vector(1 to 2));
end entity pair_user;

architecture a of pair_user is
  quantity v across t(1) to t(2);
begin
end architecture a;

library ieee;
use ieee.electrical_systems.all;

entity t is
end entity t;

architecture a of t is
  terminal n : electrical_vector(0 to 1);
begin
  missing : entity work.pair_user port map (t(1) => n(0));
  outside : entity work.pair_user port map (t(1) => n(0), t(3) => n(1));
  twice : entity work.pair_user port map (t(1) => n(0), t(1) => n(1));
end architecture a;
