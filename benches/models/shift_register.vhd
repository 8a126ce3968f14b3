-- vams: stop 10 us
--
-- shift_register: many processes and signals (issue 23's kernel benchmark beside
-- counter.vhd): a 1000-stage shift register clocked every 10 ns, one process per stage
-- (`process (clk)`, 2000 activations per clock period), fed by a linear feedback of its
-- last stages so that about half the stages change at each rising edge. Plain VHDL, so that
-- `ghdl -r` runs the same model.

entity shift_register is
  generic (n : positive := 1000);
end entity shift_register;

architecture bench of shift_register is
  signal clk : bit := '0';
  signal q : bit_vector(0 to n) := (others => '0');
begin
  clock : process
  begin
    wait for 5 ns;
    clk <= not clk;
  end process clock;

  feed : process (clk)
  begin
    if clk = '1' then
      q(0) <= not (q(n) xor q(n - 2));
    end if;
  end process feed;

  stages : for i in 1 to n generate
    stage : process (clk)
    begin
      if clk = '1' then
        q(i) <= q(i - 1);
      end if;
    end process stage;
  end generate stages;
end architecture bench;
