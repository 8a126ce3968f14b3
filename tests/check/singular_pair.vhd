-- Two equations both fix x while y is in neither: the counts agree but the pair is
-- structurally singular (over-determined x, under-determined y).
entity singular_pair is
end entity singular_pair;

architecture a of singular_pair is
  quantity x, y : real;
begin
  x == 1.0;
  2.0 * x == 3.0;
end architecture a;
