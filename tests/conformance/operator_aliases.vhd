-- vams: stop 1 ns
--
-- Aliases of predefined operators (LRM 4.3.3.2), as the aliases chapter writes them: an
-- operator symbol standing for another operator on bits (`alias "*" is "and" [bit, bit
-- return bit];`), and a name standing for one (`bit_xor(a, b)`, `flip(b)`). The aliased
-- symbol applies only where analysis chose the alias: `3 * 4` still multiplies.
entity tb_operator_aliases is
end entity tb_operator_aliases;

architecture test of tb_operator_aliases is
  alias "*" is "and" [bit, bit return bit];
  alias "+" is "or" [bit, bit return bit];
  alias bit_xor is "xor" [bit, bit return bit];
  alias flip is "not" [bit return bit];
begin
  process
    variable a : bit := '1';
    variable b : bit := '0';
  begin
    assert (a * b) = '0' report "a * b" severity error;
    assert (a + b) = '1' report "a + b" severity error;
    assert bit_xor(a, b) = '1' report "bit_xor" severity error;
    assert flip(b) = '1' report "flip" severity error;
    assert 3 * 4 = 12 report "integer * still multiplies" severity error;
    wait;
  end process;
end architecture test;
