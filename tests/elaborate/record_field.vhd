entity t is end;
architecture a of t is
  type pair is record
    a, b : real;
    bits : bit_vector(1 downto 0);
  end record;
  constant p : pair := (1.0, 2.0, "00");
  signal s : pair;
  quantity x : real;
begin
  x == p.c;
  process begin
    s.bits(1) <= '1';
    wait;
  end process;
end;
