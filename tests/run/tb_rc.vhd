-- vams: stop 5 ms
--
-- tb_rc: the low pass of rc.vhd checked against its closed form at two times.
-- vout(2 ms) = 1 - exp(-1) = 0.63212, vout(4 ms) = 1 - exp(-3) = 0.95021.

-- The cell under test comes first: VHDL analyses a unit before its users.

library ieee;
use ieee.electrical_systems.all;

entity rc_cell is
  generic (
    r : real := 1.0e3;   -- [Ohm]
    c : real := 1.0e-6   -- [F]
  );
  port (terminal outp : electrical);
end entity rc_cell;

architecture behavioral of rc_cell is
  terminal inp : electrical;
  quantity vin across iin through inp to electrical_ref;
  quantity vr across ir through inp to outp;
  quantity vout across ic through outp to electrical_ref;
  signal drive : real := 0.0;
begin
  vin == drive;
  vr == r * ir;
  ic == c * vout'dot;
  drive <= 1.0 after 1 ms;
end architecture behavioral;

library ieee;
use ieee.electrical_systems.all;

entity tb_rc is
end entity tb_rc;

architecture bench of tb_rc is
  terminal outp : electrical;
  quantity vout across outp to electrical_ref;
begin
  dut : entity work.rc_cell
    port map (outp => outp);

  check : process
  begin
    wait for 2 ms;
    assert abs(vout - 0.63212) < 5.0e-3
      report "vout(2 ms) = " & real'image(vout) & ", expected 0.63212"
      severity error;
    wait for 2 ms;
    assert abs(vout - 0.95021) < 5.0e-3
      report "vout(4 ms) = " & real'image(vout) & ", expected 0.95021"
      severity error;
    wait;
  end process check;
end architecture bench;
