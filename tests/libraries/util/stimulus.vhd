-- A resource library for tests/libraries/uses_util.vhd, analysed as `--lib util=...`.
package stimulus is
  constant step : delay_length := 2 ns;
  function doubled (x : integer) return integer;
end package stimulus;

package body stimulus is
  function doubled (x : integer) return integer is
  begin
    return 2 * x;
  end function doubled;
end package body stimulus;

entity pulse_source is
  port (s : out bit);
end entity pulse_source;

architecture ideal of pulse_source is
begin
  s <= '1' after work.stimulus.step;
end architecture ideal;
