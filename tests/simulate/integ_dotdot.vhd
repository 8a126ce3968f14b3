-- 'integ and 'dot'dot of x = t^3: x'integ = t^4 / 4, x'dot'dot = 6 t.
entity integ_dotdot is
end entity integ_dotdot;

architecture test of integ_dotdot is
  quantity x, xi, xdd : real;
begin
  x == now * now * now;
  xi == x'integ;
  xdd == x'dot'dot;
end architecture test;
