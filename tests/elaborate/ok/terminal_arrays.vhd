-- top: t
-- Array natures (the stdlib's electrical_vector, a constrained one of our own, subnatures of
-- both), terminal arrays with indexed names in port maps and branch quantities, whole-array
-- terminal ports (unconstrained, and constrained with other bounds than the actual), element
-- associations of a port array, and
-- quantity arrays read and written by index.
library ieee;
use ieee.electrical_systems.all;

package bus_natures is
  nature bus3 is array (1 to 3) of electrical;
  subnature wire_vector is electrical_vector;
  subnature pair is electrical_vector(0 to 1);
end package bus_natures;

library ieee;
use ieee.electrical_systems.all;

entity res is
  port (terminal p, m : electrical);
end entity res;

architecture a of res is
  quantity v across i through p to m;
begin
  v == 1.0e3 * i;
end architecture a;

library ieee;
use ieee.electrical_systems.all;
use work.bus_natures.all;

-- An unconstrained port: its range is the actual's.
entity ground_all is
  port (terminal t : wire_vector);
end entity ground_all;

architecture a of ground_all is
begin
  g : for k in t'range generate
    r : entity work.res port map (p => t(k), m => electrical_ref);
  end generate g;
end architecture a;

library ieee;
use ieee.electrical_systems.all;
use work.bus_natures.all;

-- A constrained port with other bounds than its actual: elements match by position.
entity top_two is
  port (terminal b : bus3);
end entity top_two;

architecture a of top_two is
  quantity v12 across b(1) to b(2);
  quantity v23 across b(3 - 0) to b(2);
begin
end architecture a;

library ieee;
use ieee.electrical_systems.all;
use work.bus_natures.all;

entity t is
end entity t;

architecture a of t is
  constant last : natural := 3;
  terminal node : electrical_vector(0 to last);
  terminal down : wire_vector(2 downto 0);
  terminal ends : pair;
  quantity vs across i_s through node(0);
  quantity q : real_vector(1 to 2) := (0.5, 0.25);
  quantity u : voltage_vector(1 to 2);
begin
  vs == 1.0;
  chain : for k in 1 to last generate
    r : entity work.res port map (p => node(k - 1), m => node(k));
  end generate chain;
  gnd : entity work.ground_all port map (t => node);
  both : entity work.top_two port map (b => down);
  pick : entity work.top_two port map (b(1) => ends(1), b(3) => electrical_ref, b(2) => node(last));
  e : entity work.res port map (p => ends(0), m => ends(1));
  q(1) == 2.0 * q(2);
  q(2) == 1.0;
  u(1) == q(1);
  u(2) == 0.0;
end architecture a;

library ieee;
use ieee.mechanical_systems.all;

-- The pre-standard vector subnature and an across subtype of an array nature.
entity shafts is
end entity shafts;

architecture a of shafts is
  terminal s : rotational_v_vector(1 to 2);
  quantity w across tq through s(1) to s(2);
  quantity speeds : angular_velocity_vector(1 to 2);
begin
  w == 1.0;
  tq == 0.0;
  speeds(1) == w;
  speeds(2) == 2.0 * w;
end architecture a;
