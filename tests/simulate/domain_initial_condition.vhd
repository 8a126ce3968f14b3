-- The textbook initial condition: a capacitor whose equation is `v == v0` while the quiescent
-- point is computed and `i == c * v'dot` afterwards, precharged to v0 = 0.25 V and charged
-- through r from a 1 V source: v(t) = 1 - 0.75 exp(-t / (r c)). `std.standard.domain` turns
-- from quiescent_domain to time_domain with an event at time 0 (LRM 1076.1, 12.6.4).
library ieee;
use ieee.electrical_systems.all;

entity precharged_capacitor is
  generic (c : real; v0 : real := 0.0);
  port (terminal p, m : electrical);
end entity precharged_capacitor;

architecture ideal of precharged_capacitor is
  quantity v across i through p to m;
begin
  if domain = quiescent_domain use
    v == v0;
  else
    i == c * v'dot;
  end use;
end architecture ideal;

library ieee;
use ieee.electrical_systems.all;

entity domain_initial_condition is
  generic (r : real := 1.0e3; c : real := 1.0e-6; v0 : real := 0.25);
end entity domain_initial_condition;

architecture test of domain_initial_condition is
  terminal n_in, n_out : electrical;
  quantity v_in across i_in through n_in to electrical_ref;
  quantity v_r across i_r through n_in to n_out;
  signal domain_events : natural := 0;
begin
  v_in == 1.0;
  v_r == r * i_r;
  c1 : entity work.precharged_capacitor
    generic map (c => c, v0 => v0)
    port map (p => n_out, m => electrical_ref);

  -- A break on the domain signal is legal and harmless.
  break on domain;

  watch : process
  begin
    assert domain = quiescent_domain report "domain during initialisation" severity failure;
    wait until domain = time_domain;
    assert now = 0 ns report "time_domain after time 0" severity failure;
    report "time domain";
    domain_events <= domain_events + 1;
    wait on domain for 1 ms;
    assert not domain'event report "domain changed twice" severity failure;
    wait;
  end process;
end architecture test;
