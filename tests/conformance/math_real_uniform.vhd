-- vams: stop 1 ns
--
-- ieee.math_real.uniform, as a Monte Carlo testbench uses it: the seeds after 1000 draws and
-- the mean of the draws are those of L'Ecuyer's generator (computed independently in Python
-- with the recurrences IEEE 1076.2 specifies), every draw lies in the open interval (0, 1).

library ieee;
use ieee.math_real.all;

entity tb_math_real_uniform is
end entity tb_math_real_uniform;

architecture test of tb_math_real_uniform is
begin
  process
    variable seed1, seed2 : positive := 1;
    variable x, sum : real := 0.0;
  begin
    for i in 1 to 1000 loop
      uniform(seed1, seed2, x);
      assert x > 0.0 and x < 1.0
        report "draw " & integer'image(i) & " outside (0, 1): " & real'image(x)
        severity error;
      sum := sum + x;
    end loop;
    assert seed1 = 1487191379 and seed2 = 2121278613
      report "seeds " & integer'image(seed1) & ", " & integer'image(seed2)
      severity error;
    assert abs (sum / 1000.0 - 0.4838719002657277) < 1.0e-12
      report "mean " & real'image(sum / 1000.0)
      severity error;
    wait;
  end process;
end architecture test;
