-- vams: stop 1 ms
--
-- The logical operators of bit against their truth tables, and a bit signal toggled with
-- `not` (a counter's least significant bit).

entity tb_bit_operators is end;
architecture t of tb_bit_operators is
  signal lsb : bit := '0';
  signal count : integer := 0;
begin
  clk : process
  begin
    wait for 10 us;
    lsb <= not lsb;
    count <= count + 1;
    if count < 9 then null; else wait; end if;
  end process;
  check : process
    variable a, b : bit;
  begin
    for i in 0 to 3 loop
      a := bit'val(i / 2); b := bit'val(i mod 2);
      assert (a and b) = bit'val((i / 2) * (i mod 2)) report "and" severity error;
      assert (a or b) = bit'val(((i / 2) + (i mod 2) + 1) / 2) report "or" severity error;
      assert (a xor b) = bit'val(((i / 2) + (i mod 2)) mod 2) report "xor" severity error;
      assert (a nand b) = not (a and b) report "nand" severity error;
      assert (a nor b) = not (a or b) report "nor" severity error;
      assert (a xnor b) = not (a xor b) report "xnor" severity error;
    end loop;
    wait for 55 us;
    assert lsb = '1' report "lsb toggles" severity error;
    wait;
  end process;
end;
