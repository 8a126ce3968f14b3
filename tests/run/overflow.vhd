-- vams: stop 20 ns
--
-- `integer` holds -2**31 to 2**31 - 1: counting past it is a run-time error, not a larger
-- number (LRM 3.1.2); so is a `natural` below 0.
entity overflow is
  generic (step : integer := 100);
end entity overflow;

architecture a of overflow is
begin
  p : process is
    variable n : natural := 10;
    variable big : integer := 2147483000;
  begin
    wait for 1 ns;
    big := big + step;
    n := n - 1;
  end process p;
end architecture a;
