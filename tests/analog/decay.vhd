-- Exponential decay x' = -x / tau from x(0) = 1: x(t) = exp(-t / tau). The BDF orders up to 5
-- carry the error down with the tolerance (issue 15).
entity decay is
  generic (tau : real := 1.0);
end entity decay;

architecture test of decay is
  quantity x : real;
begin
  x'dot == -x / tau;
  break x => 1.0;
end architecture test;
