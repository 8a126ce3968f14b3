-- slew: a slew-rate limit in the signal path: `vams ac` refuses it (a process shapes it in
-- time; its small-signal response is not defined), pointing at the attribute.
-- vams: stop 1 ms
entity tb_slew is end entity;
architecture bench of tb_slew is
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin, vout : real;
begin
  vin == ac_in;
  vout == vin'slew(1.0e3);
end architecture;
