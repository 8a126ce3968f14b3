-- 'dot'dot and 'integ: the second-order step response written with x'dot'dot,
-- x'dot'dot + 2 zeta w x'dot + w^2 x == w^2 s (s steps 0 -> 1 at 1 ms), and its integral
-- x'integ (0 at the quiescent point).
entity integ_dotdot is
  generic (w : real := 1.0e3; zeta : real := 0.2);
end entity integ_dotdot;

architecture test of integ_dotdot is
  signal s : real := 0.0;
  quantity x, xi : real;
begin
  x'dot'dot + 2.0 * zeta * w * x'dot + w * w * x == w * w * s;
  xi == x'integ;
  s <= 1.0 after 1 ms;
end architecture test;
