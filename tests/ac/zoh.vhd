-- zoh: a sample-and-hold in the signal path: `vams ac` refuses it (its frequency response
-- is not the small-signal model's), pointing at the attribute.
-- vams: stop 1 ms
entity tb_zoh is end entity;
architecture bench of tb_zoh is
  quantity ac_in : real spectrum 1.0, 0.0;
  quantity vin, vout : real;
begin
  vin == ac_in;
  vout == vin'zoh(1.0e-3);
end architecture;
