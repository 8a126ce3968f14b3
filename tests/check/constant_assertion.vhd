-- A constant computed by a function whose assertion fails for the generics' defaults.
entity constant_assertion is
  generic (length : real := 0.0);
end entity constant_assertion;

architecture a of constant_assertion is
  function area (l : real) return real is
  begin
    assert l > 0.0 report "channel length not specified" severity error;
    return l * l;
  end function area;

  constant a0 : real := area(length);
  quantity x : real;
begin
  x == a0;
end architecture a;
