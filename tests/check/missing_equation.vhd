-- Two free quantities, one equation: the count rule fails.
entity missing_equation is
end entity missing_equation;

architecture a of missing_equation is
  quantity x, y : real;
begin
  x'dot == -x + 1.0;
end architecture a;
