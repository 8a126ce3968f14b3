-- Elements, slices and record fields of variables as the actuals of `out` and `inout`
-- parameters: passed by value and written back after the call (LRM 2.1.1.1).
-- vams: stop 1 ns

entity tb_part_actuals is
end entity tb_part_actuals;

architecture test of tb_part_actuals is
  type int_array is array (1 to 4) of integer;
  type point is record
    x, y : integer;
  end record point;
  type segment is record
    head, tail : point;
  end record segment;

  procedure swap (a, b : inout integer) is
    variable t : integer;
  begin
    t := a;
    a := b;
    b := t;
  end procedure swap;

  procedure fill (v : out bit_vector; b : in bit) is
  begin
    v := (v'range => b);
  end procedure fill;

  procedure move (p : inout point; dx, dy : in integer) is
  begin
    p.x := p.x + dx;
    p.y := p.y + dy;
  end procedure move;
begin
  process is
    variable a : int_array := (1, 2, 3, 4);
    variable bits : bit_vector(7 downto 0) := (others => '0');
    variable s : segment := ((0, 0), (5, 5));
  begin
    swap(a(1), a(4));
    assert a = (4, 2, 3, 1);
    for i in 1 to 2 loop
      swap(a(i), a(i + 1));
    end loop;
    assert a = (2, 3, 4, 1) report "swapped by computed indexes";
    fill(bits(3 downto 0), '1');
    assert bits = "00001111";
    move(s.tail, 1, -2);
    swap(s.head.x, s.tail.y);
    assert s = ((3, 0), (6, 0));
    wait;
  end process;
end architecture test;
