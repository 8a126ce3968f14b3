-- vams: stop 3 ms
--
-- A subnature with tolerance groups of its own (Ashenden, Peterson and Teegarden, chapter 6):
-- its terminals connect to the base nature's, its branch quantities carry its groups, which
-- `'tolerance` reads and other quantities reuse. The circuit: an RC low pass whose capacitor
-- sits between a subnature terminal and ground, charging from 0 V to 2 V with RC = 0.5 ms.

library ieee;
use ieee.math_real.all;

package accurate is
  subtype voltage is real tolerance "default_voltage";
  subtype current is real tolerance "default_current";
  nature electrical is voltage across current through ground reference;
  subnature accurate_electrical is electrical
    tolerance "accurate_voltage" across "accurate_current" through;
end package accurate;

library ieee;
use ieee.math_real.all;
use work.accurate.all;

entity tb_subnature_tolerance is
end entity tb_subnature_tolerance;

architecture test of tb_subnature_tolerance is
  terminal src : electrical;
  terminal cap : accurate_electrical;
  quantity v_src across i_src through src to ground;
  quantity v_r across i_r through src to cap;
  quantity v_c across i_c through cap to ground;
  quantity v_plain across src;
  -- A quantity declared with a branch quantity's group.
  quantity v_copy : voltage tolerance v_c'tolerance;
  quantity i_copy : current tolerance i_c'tolerance;
begin
  v_src == 2.0;
  v_r == 500.0 * i_r;
  if domain = quiescent_domain use
    v_c == 0.0;
  else
    i_c == 1.0e-6 * v_c'dot;
  end use;
  v_copy == v_c;
  i_copy == i_c;

  check : process
  begin
    assert v_c'tolerance = "accurate_voltage"
      report "v_c'tolerance = " & v_c'tolerance severity error;
    assert i_c'tolerance = "accurate_current"
      report "i_c'tolerance = " & i_c'tolerance severity error;
    assert v_src'tolerance = "default_voltage"
      report "v_src'tolerance = " & v_src'tolerance severity error;
    assert v_plain'tolerance = "default_voltage"
      report "v_plain'tolerance = " & v_plain'tolerance severity error;
    assert v_copy'tolerance = "accurate_voltage"
      report "v_copy'tolerance = " & v_copy'tolerance severity error;
    assert i_copy'tolerance = "accurate_current"
      report "i_copy'tolerance = " & i_copy'tolerance severity error;
    wait for 1 ms;
    -- v(t) = 2 (1 - exp(-t / 0.5 ms)).
    assert abs(v_c - 2.0 * (1.0 - exp(-2.0))) < 1.0e-2
      report "v_c(1 ms) = " & real'image(v_c) severity error;
    wait;
  end process check;
end architecture test;
