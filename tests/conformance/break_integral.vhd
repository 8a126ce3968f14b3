-- vams: stop 4 ms
--
-- A break that sets the state of an integral, as the book's bouncing ball reverses its
-- velocity: `break acceleration'integ => - acceleration'integ;`. With a constant
-- acceleration of 1 the integral is t until the break at 1 ms, then -1 ms + (t - 1 ms).

entity tb_break_integral is
end entity tb_break_integral;

architecture test of tb_break_integral is
  quantity acceleration, velocity : real;
begin
  acceleration == 1.0;
  velocity == acceleration'integ;

  process
  begin
    wait for 1 ms;
    break acceleration'integ => - acceleration'integ;
    wait for 2 ms;
    assert abs (velocity - 1.0e-3) < 1.0e-9
      report "velocity at 3 ms: " & real'image(velocity) severity error;
    wait;
  end process;

  check_before : process
  begin
    wait for 0.5 ms;
    assert abs (velocity - 0.5e-3) < 1.0e-9
      report "velocity at 0.5 ms: " & real'image(velocity) severity error;
    wait for 1 ms;
    assert abs (velocity + 0.5e-3) < 1.0e-9
      report "velocity at 1.5 ms: " & real'image(velocity) severity error;
    wait;
  end process;
end architecture test;
