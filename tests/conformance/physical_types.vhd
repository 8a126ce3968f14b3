-- Physical types of the user's own (LRM 3.1.3): units, literals, arithmetic with integers
-- and reals, the division of two values, attributes, 'image in the primary unit, 'value.
-- vams: stop 1 ns

entity tb_physical_types is
end entity tb_physical_types;

architecture test of tb_physical_types is
  type resistance is range 0 to 1E9
    units
      ohm;
      kohm = 1000 ohm;
      Mohm = 1000 kohm;
    end units resistance;
  type length is range 0 to 1E9
    units
      um;                  -- primary unit: micron
      mm = 1000 um;        -- metric units
      m = 1000 mm;
      inch = 25400 um;     -- imperial units
      foot = 12 inch;
    end units length;
  constant r_load : resistance := 4.7 kohm;
  signal r_now : resistance := 100 ohm;
begin
  process is
    variable r : resistance;
    variable l1, l2 : length;
    variable n : integer;
  begin
    assert r = 0 ohm report "default: the type's left bound";
    assert r_load = 4700 ohm and r_load > 4 kohm and r_load < 1 Mohm;
    r := r_load + 300 ohm;
    assert r = 5 kohm;
    r := r * 2;
    assert r = 10 kohm;
    r := 2.5 * r;
    assert r = 25 kohm;
    r := r / 5;
    assert r = 5000 ohm;
    n := r / 1 kohm;
    assert n = 5;
    assert abs (-r) = r;
    assert resistance'image(2 kohm) = "2000 ohm";
    assert resistance'value("5 Mohm") = 5_000_000 ohm;
    assert resistance'left = 0 ohm and resistance'high = 1E9 ohm;
    l1 := 1 inch;
    assert l1 = 25400 um report length'image(l1);
    assert 1 foot = 304800 um and 1 foot / 1 inch = 12;
    l2 := 3 mm + 500 um;
    assert l2 = 3500 um and l2 < l1;
    r_now <= r_load;
    wait for 1 ns;
    assert r_now = 4.7 kohm;
    wait;
  end process;
end architecture test;
