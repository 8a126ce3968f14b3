-- 'ltf of a unit step through w^2 / (s^2 + 2 zeta w s + w^2), underdamped: the classic step
-- response 1 - exp(-zeta w t) (cos(wd t) + zeta w / wd sin(wd t)), wd = w sqrt(1 - zeta^2).
entity ltf_second_order is
  generic (w : real := 1.0e3; zeta : real := 0.2);
end entity ltf_second_order;

architecture test of ltf_second_order is
  constant num : real_vector := (0 => w * w);
  constant den : real_vector := (w * w, 2.0 * zeta * w, 1.0);
  signal s : real := 0.0;
  quantity u, y : real;
begin
  u == s;
  y == u'ltf(num, den);
  s <= 1.0 after 1 ms;
end architecture test;
