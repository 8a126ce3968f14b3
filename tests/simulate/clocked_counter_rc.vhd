-- A counter clocked every nanosecond beside an RC low pass it does not touch, and a process
-- that samples the capacitor voltage every 10 us: only the samples need analog solution
-- points; the clock edges run between the integrator's steps.
library ieee;
use ieee.electrical_systems.all;

entity clocked_counter_rc is
end entity clocked_counter_rc;

architecture test of clocked_counter_rc is
  signal clk : bit := '0';
  signal count : natural := 0;
  signal sampled : real := 0.0;
  terminal n1, n2 : electrical;
  quantity v_in across i_in through n1 to electrical_ref;
  quantity v_r across i_r through n1 to n2;
  quantity v_c across i_c through n2 to electrical_ref;
begin
  clk <= not clk after 0.5 ns;

  counter : process (clk) is
  begin
    if clk = '1' then
      count <= count + 1;
    end if;
  end process counter;

  v_in == 1.0;
  v_r == 1.0e3 * i_r;
  if domain = quiescent_domain use
    v_c == 0.0;
  else
    i_c == 1.0e-8 * v_c'dot;                -- tau = 10 us
  end use;

  sample : process is
  begin
    wait for 10 us;
    sampled <= v_c;
  end process sample;
end architecture test;
