-- vams: stop 5 ms
-- tb_decay: x' = -x / tau from x(0) = 1, so x(t) = exp(-t / tau): it falls through
-- exp(-1) at t = tau, its mean over [0, T] is tau (1 - exp(-T / tau)) / T, and it
-- enters the band 0.01 around 0 for good at tau ln(100). `tau_max` makes runs fail on
-- purpose: an assertion of severity failure when tau exceeds it, an elaboration error
-- (a positive generic set to 0) when `steps` is 0.
entity tb_decay is
  generic (
    tau   : real := 1.0e-3;
    tau_max : real := 1.0;
    steps : positive := 1
  );
end entity tb_decay;

architecture test of tb_decay is
  quantity x : real;
begin
  x'dot == -x / tau;
  break x => 1.0;

  check : process
  begin
    assert tau <= tau_max report "tau beyond tau_max" severity failure;
    wait;
  end process check;
end architecture test;
