-- vams: stop 1 ms
--
-- Quantity ports of array types, as the book's seven-segment display declares them
-- (`quantity segment_illuminances : out illuminance_vector(1 to 7)`): associated whole, by
-- slice, element by element (`y(1) => a, y(2 to 3) => b(0 to 1)`), and left open.

entity doubler is
  port (quantity inputs : in real_vector(1 to 3);
        quantity outputs : out real_vector(1 to 3));
end entity doubler;

architecture ideal of doubler is
begin
  outputs == (2.0 * inputs(1), 2.0 * inputs(2), 2.0 * inputs(3));
end architecture ideal;

entity tb_quantity_array_ports is
end entity tb_quantity_array_ports;

architecture test of tb_quantity_array_ports is
  quantity source : real_vector(0 to 4);
  quantity whole : real_vector(1 to 3);
  quantity single : real;
  quantity pair : real_vector(0 to 1);
begin
  source == (1.0, 2.0, 3.0, 4.0, 5.0);

  u_whole : entity work.doubler(ideal)
    port map (inputs => source(0 to 2), outputs => whole);
  u_elements : entity work.doubler(ideal)
    port map (inputs(1) => source(4), inputs(2 to 3) => source(2 to 3),
              outputs(1) => single, outputs(2 to 3) => pair(0 to 1));
  u_open : entity work.doubler(ideal)
    port map (inputs => source(2 to 4), outputs => open);

  check : process
  begin
    wait for 0.5 ms;
    assert whole(1) = 2.0 and whole(2) = 4.0 and whole(3) = 6.0
      report "whole: " & real'image(whole(1)) & real'image(whole(2)) & real'image(whole(3))
      severity error;
    assert single = 10.0 report "single: " & real'image(single) severity error;
    assert pair(0) = 6.0 and pair(1) = 8.0
      report "pair: " & real'image(pair(0)) & real'image(pair(1)) severity error;
    wait;
  end process check;
end architecture test;
