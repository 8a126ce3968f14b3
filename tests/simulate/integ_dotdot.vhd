-- 'integ and 'dot'dot of x = t^3 (from x'dot == 3 t^2, x(0) = 0): x'integ = t^4 / 4,
-- x'dot'dot = 6 t.
entity integ_dotdot is
end entity integ_dotdot;

architecture test of integ_dotdot is
  quantity x, xi, xdd : real;
begin
  x'dot == 3.0 * now * now;
  break x => 0.0;
  xi == x'integ;
  xdd == x'dot'dot;
end architecture test;
