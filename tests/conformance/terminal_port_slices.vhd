-- vams: stop 1 ms
--
-- A terminal array port associated by slices and elements, as the book's seven-segment
-- display connects its anodes: `segment_anodes(2) => hour_anode_2, segment_anodes(4 to 7) =>
-- anodes_unused(2 to 5)`. Each element of the port loads its terminal with 1 kOhm; each
-- source's current is its voltage over 1 kOhm, negated.

library ieee_proposed;
use ieee_proposed.electrical_systems.all;

entity load_bank is
  port (terminal t : electrical_vector(1 to 4));
end entity load_bank;

architecture ideal of load_bank is
  quantity v across i through t;
begin
  i == (v(1) / 1.0e3, v(2) / 1.0e3, v(3) / 1.0e3, v(4) / 1.0e3);
end architecture ideal;

library ieee_proposed;
use ieee_proposed.electrical_systems.all;

entity tb_terminal_port_slices is
end entity tb_terminal_port_slices;

architecture test of tb_terminal_port_slices is
  terminal single : electrical;
  terminal spare : electrical_vector(0 to 3);
  quantity vs across isingle through single;
  quantity vspare across ispare through spare;
begin
  vs == 1.0;
  vspare == (2.0, 3.0, 4.0, 5.0);

  u_bank : entity work.load_bank(ideal)
    port map (t(1) => single, t(2 to 4) => spare(1 to 3));

  check : process
  begin
    wait for 0.5 ms;
    assert abs (isingle + 1.0e-3) < 1.0e-12 report "isingle: " & real'image(isingle) severity error;
    assert abs (ispare(0)) < 1.0e-12 report "ispare(0): " & real'image(ispare(0)) severity error;
    assert abs (ispare(1) + 3.0e-3) < 1.0e-12 report "ispare(1): " & real'image(ispare(1)) severity error;
    assert abs (ispare(3) + 5.0e-3) < 1.0e-12 report "ispare(3): " & real'image(ispare(3)) severity error;
    wait;
  end process check;
end architecture test;
