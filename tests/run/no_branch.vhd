-- A simultaneous if without `else`: its equations exist while one of its conditions holds.
-- x falls through 0 at t = 1 s, where neither branch covers it.
entity no_branch is
end entity no_branch;

architecture a of no_branch is
  quantity x, y : real;
begin
  x == 1.0 - now;
  region : if x > 0.5 use
    y == 2.0 * x;
  elsif x <= 0.5 and x > 0.0 use
    y == x + 0.5;
  end use;
end architecture a;
