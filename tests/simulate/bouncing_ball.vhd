-- A ball dropped from h0 bounces with restitution e: impact k (k = 1, 2, ...) happens at
-- t_1 = sqrt(2 h0 / g), t_{k+1} = t_k + 2 e^k sqrt(2 g h0) / g.
entity bouncing_ball is
  generic (h0 : real := 1.0; g : real := 9.81; e : real := 0.8);
end entity bouncing_ball;

architecture test of bouncing_ball is
  quantity y : real;  -- height [m]
  quantity v : real;  -- velocity [m/s], up positive
begin
  y'dot == v;
  v'dot == -g;
  break y => h0, v => 0.0;

  bounce : process
  begin
    wait until not y'above(0.0);
    report "impact";
    break v => -e * v;
  end process bounce;
end architecture test;
