-- no_root: x * x = p has no real solution for p < 0; a sweep of p from 1 down stops there,
-- keeping the points before it.
-- vams: stop 1 ms
entity tb_no_root is
  generic (p : real := 1.0);
end entity;
architecture bench of tb_no_root is
  quantity x : real := 1.0;
begin
  x * x == p;
end architecture;
