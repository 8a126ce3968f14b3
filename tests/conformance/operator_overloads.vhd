-- vams: stop 1 ns
--
-- A function declared in an architecture with the profile of a predefined operator hides
-- that operator there (LRM 10.3): `x < y` and `"<"(x, y)` on bit_vector call the
-- architecture's signed comparison, and `a + b` on integer the architecture's saturating
-- addition, while `std.standard."<"` still names the predefined one.

entity tb_operator_overloads is
end entity tb_operator_overloads;

architecture test of tb_operator_overloads is

  function "<" (l, r : bit_vector) return boolean is
    variable tmp1 : bit_vector(l'range) := l;
    variable tmp2 : bit_vector(r'range) := r;
  begin
    tmp1(tmp1'left) := not tmp1(tmp1'left);
    tmp2(tmp2'left) := not tmp2(tmp2'left);
    return std.standard."<"(tmp1, tmp2);
  end function "<";

  function "+" (l, r : integer) return integer is
    constant ceiling : integer := 100;
  begin
    if std.standard."+"(l, r) > ceiling then
      return ceiling;
    end if;
    return std.standard."+"(l, r);
  end function "+";

begin

  process
    variable minus_eight : bit_vector(3 downto 0) := "1000";
    variable seven : bit_vector(3 downto 0) := "0111";
    variable a, b : integer := 60;
  begin
    assert minus_eight < seven report "x < y is the signed comparison" severity error;
    assert "<"(minus_eight, seven) report """<""(x, y) is the signed comparison" severity error;
    assert not std.standard."<"(minus_eight, seven)
      report "std.standard.""<"" is the predefined comparison" severity error;
    assert a + b = 100 report "a + b saturates: " & integer'image(a + b) severity error;
    wait;
  end process;

end architecture test;
