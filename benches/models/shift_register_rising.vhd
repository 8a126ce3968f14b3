-- vams: stop 10 us
--
-- shift_register_rising: shift_register.vhd written the usual way, with `clk` a std_ulogic
-- and `if rising_edge(clk) then` (ieee.std_logic_1164) in each of its 1001 processes
-- instead of `if clk = '1' then` (issue 23): a 1000-stage shift register clocked every 10 ns,
-- one process per stage (`process (clk)`, 2000 activations per clock period), fed by a
-- linear feedback of its last stages. Plain VHDL, so that `ghdl -r` runs the same model.

library ieee;
use ieee.std_logic_1164.all;

entity shift_register_rising is
  generic (n : positive := 1000);
end entity shift_register_rising;

architecture bench of shift_register_rising is
  signal clk : std_ulogic := '0';
  signal q : bit_vector(0 to n) := (others => '0');
begin
  clock : process
  begin
    wait for 5 ns;
    clk <= not clk;
  end process clock;

  feed : process (clk)
  begin
    if rising_edge(clk) then
      q(0) <= not (q(n) xor q(n - 2));
    end if;
  end process feed;

  stages : for i in 1 to n generate
    stage : process (clk)
    begin
      if rising_edge(clk) then
        q(i) <= q(i - 1);
      end if;
    end process stage;
  end generate stages;
end architecture bench;
