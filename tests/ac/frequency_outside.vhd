-- frequency_outside: FREQUENCY read in an ordinary equation, which the LRM does not allow.
entity frequency_outside is end entity;
architecture bench of frequency_outside is
  quantity x : real;
begin
  x == frequency;
end architecture;
