-- Branch quantities between a terminal array and one terminal (LRM 1076.1 4.3.1.6): arrays
-- of branch quantities, one per element; a process reads them by a computed index.
-- vams: stop 1 ms

library ieee;
use ieee.electrical_systems.all;

entity tb_terminal_array_branches is
end entity tb_terminal_array_branches;

architecture test of tb_terminal_array_branches is
  terminal bus_lines : electrical_vector(1 to 3);
  -- Three 1 kOhm resistors from the lines to ground, and three current sources into them.
  quantity v_load across i_load through bus_lines to electrical_ref;
  quantity v_src across i_src through electrical_ref to bus_lines;
  signal above_threshold : bit_vector(1 to 3) := "000";
begin
  loads : for k in 1 to 3 generate
    v_load(k) == 1.0e3 * i_load(k);
    i_src(k) == real(k) * 1.0e-3;
  end generate loads;

  detect : process is
  begin
    wait for 0.5 ms;
    for index in 1 to 3 loop
      assert abs (v_load(index) - real(index)) < 1.0e-6
        report "line " & integer'image(index) & " at " & real'image(v_load(index));
      if v_load(index) > 1.5 then
        above_threshold(index) <= '1';
      end if;
    end loop;
    wait for 0.1 ms;
    assert above_threshold = "011";
    assert abs (v_src(2) + 2.0) < 1.0e-6 report "the source's across is ground minus the line";
    wait;
  end process detect;
end architecture test;
