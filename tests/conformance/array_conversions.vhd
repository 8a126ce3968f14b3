-- Conversions between closely related array types (LRM 7.3.5): the same element type,
-- the operand's bounds kept for an unconstrained target, and string <-> another array of
-- characters.
-- vams: stop 1 ns

entity tb_array_conversions is
end entity tb_array_conversions;

architecture test of tb_array_conversions is
  type display_string is array (integer range <>) of character;
  subtype display_line is display_string(0 to 5);
  type word is array (natural range <>) of bit;
  type other_word is array (natural range <>) of bit;
begin
  process is
    variable item_name : string(1 to 6) := "widget";
    variable display : display_line;
    variable w : word(7 downto 0) := "10100101";
    variable o : other_word(7 downto 0);
    variable back : string(1 to 6);
  begin
    display := display_string(item_name);
    assert display(0) = 'w' and display(5) = 't';
    back := string(display);
    assert back = "widget";
    o := other_word(w);
    assert o(7) = '1' and o(6) = '0' and o = "10100101";
    assert word(o) = w;
    wait;
  end process;
end architecture test;
