-- 'ltf of a unit step through 1 / (1 + s tau): y(t) = 1 - exp(-(t - 1 ms) / tau) after the
-- step at 1 ms.
entity ltf_first_order is
  generic (tau : real := 1.0e-3);
end entity ltf_first_order;

architecture test of ltf_first_order is
  constant num : real_vector := (0 => 1.0);
  constant den : real_vector := (1.0, tau);
  signal s : real := 0.0;
  quantity u, y : real;
begin
  u == s;
  y == u'ltf(num, den);
  s <= 1.0 after 1 ms;
end architecture test;
