-- vams: stop 10 ms
--
-- An expression as the actual of a quantity port of mode in, as the book's ADC with a
-- reference writes it (`v_ref => v_supply / 2.0`): the port equals the expression at every
-- time. A constant and a signal are expressions too. Checked against the closed forms (to
-- the solver's tolerance where the process samples between analog points).

library ieee_proposed;
use ieee_proposed.electrical_systems.all;

entity scaled_copy is
  generic (gain : real := 3.0);
  port (quantity v_ref : in real;
        quantity output : out real);
end entity scaled_copy;

architecture ideal of scaled_copy is
begin
  output == gain * v_ref;
end architecture ideal;

entity tb_quantity_port_expressions is
end entity tb_quantity_port_expressions;

library ieee;
use ieee.math_real.all;

architecture test of tb_quantity_port_expressions is
  constant offset : real := 2.0;
  signal level : real := 1.0;
  quantity v_supply, half, fixed, stepped : real;
begin
  v_supply == 5.0 + sin(2.0 * math_pi * 100.0 * now);

  u_half : entity work.scaled_copy(ideal)
    port map (v_ref => v_supply / 2.0, output => half);
  u_fixed : entity work.scaled_copy(ideal)
    generic map (gain => 0.5)
    port map (offset, fixed);
  u_step : entity work.scaled_copy(ideal)
    port map (v_ref => level, output => stepped);

  level <= 4.0 after 5 ms;

  check : process
  begin
    for k in 1 to 9 loop
      wait for 1 ms;
      assert abs (half - 1.5 * v_supply) < 1.0e-9
        report "half: " & real'image(half) severity error;
      assert abs (half - 1.5 * (5.0 + sin(2.0 * math_pi * 100.0 * real(k) * 1.0e-3))) < 1.0e-2
        report "half against the closed form: " & real'image(half) severity error;
      assert fixed = 1.0 report "fixed: " & real'image(fixed) severity error;
      -- At 5 ms the process sees the analog point solved before the signal changed.
      if k <= 5 then
        assert stepped = 3.0 report "stepped before: " & real'image(stepped) severity error;
      else
        assert stepped = 12.0 report "stepped after: " & real'image(stepped) severity error;
      end if;
    end loop;
    wait;
  end process check;
end architecture test;
