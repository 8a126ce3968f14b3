-- RC charge whose resistance comes from a function inlined into the equation:
-- r_of(t) = r0 for every t here (its time term is scaled by zero), so
-- v_c(t) = 1 - exp(-t / (r0 c)).
library ieee;
use ieee.electrical_systems.all;

entity sub_rc_function is
  generic (r0 : real := 1.0e3; c : real := 1.0e-6);
end entity sub_rc_function;

architecture test of sub_rc_function is
  function r_of (t : real) return real is
    constant drift : real := 0.0;
    variable r : real := r0;
  begin
    r := r * (1.0 + drift * t);
    return r;
  end function r_of;

  function div (num : real; den : real) return real is
  begin
    return num / den;
  end function div;

  terminal n_in, n_out : electrical;
  quantity v_in across i_in through n_in to electrical_ref;
  quantity v_r across i_r through n_in to n_out;
  quantity v_c across i_c through n_out to electrical_ref;
begin
  v_in == 1.0;
  i_r == div(v_r, r_of(v_c));
  i_c == c * v_c'dot;
  break v_c => 0.0;
end architecture test;
