-- vams: stop 10 ms
--
-- Quantity attributes of whole quantity arrays, element by element, as the book's quad
-- op-amp writes them (`real_vector(v_out) == v_amplified'slew(1.0e6, -1.0e6);`, the left side
-- a conversion between closely related array types): `'slew`, `'integ` and `'delayed` of a
-- real_vector, checked against their closed forms. The inputs rise ten times faster than the
-- slew limits allow, to 4 V and to -8 V.

library ieee_proposed;
use ieee_proposed.electrical_systems.all;
library ieee;
use ieee.math_real.all;

entity tb_array_quantity_attributes is
end entity tb_array_quantity_attributes;

architecture test of tb_array_quantity_attributes is
  -- Open outputs: their currents are zero, the slew equations set their voltages.
  terminal outputs : electrical_vector(1 to 2);
  quantity v_out across i_out through outputs;
  quantity input, area, late : real_vector(1 to 2);
begin
  input(1) == realmin(1.0e4 * now, 4.0);
  input(2) == -2.0 * input(1);
  -- Slew-limited to 1 V/ms rising and 2 V/ms falling.
  real_vector(v_out) == input'slew(1.0e3, -2.0e3);
  area == input'integ;
  late == input'delayed(1.0e-3);

  check : process
  begin
    wait for 3 ms;
    assert abs (v_out(1) - 3.0) < 1.0e-2 report "v_out(1) = " & real'image(v_out(1)) severity error;
    assert abs (v_out(2) + 6.0) < 1.0e-2 report "v_out(2) = " & real'image(v_out(2)) severity error;
    -- The integral of the input: 4 V from 0.4 ms, after a ramp worth 0.8 mVs.
    assert abs (area(1) - (0.8e-3 + 4.0 * 2.6e-3)) < 1.0e-5
      report "area(1) = " & real'image(area(1)) severity error;
    assert abs (area(2) + 2.0 * (0.8e-3 + 4.0 * 2.6e-3)) < 2.0e-5
      report "area(2) = " & real'image(area(2)) severity error;
    wait for 6 ms;   -- settled at 4 ms
    assert abs (v_out(1) - 4.0) < 1.0e-3 report "v_out(1) = " & real'image(v_out(1)) severity error;
    assert abs (v_out(2) + 8.0) < 1.0e-3 report "v_out(2) = " & real'image(v_out(2)) severity error;
    assert abs (late(2) + 8.0) < 1.0e-6 report "late(2) = " & real'image(late(2)) severity error;
    wait;
  end process check;
end architecture test;
