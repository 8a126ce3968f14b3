-- vams: stop 20 ns
--
-- Integer objects outside their subtype's range are run-time errors (LRM 8.4, 8.5): the
-- counter `k : integer range 0 to 7` reaches 8 at 8 ns; with `-g wrap=true` it wraps and the
-- run completes. A `positive` variable starts at 1 (its subtype's left bound).
entity range_check is
  generic (wrap : boolean := false);
end entity range_check;

architecture a of range_check is
  signal k : integer range 0 to 7 := 0;
begin
  count : process is
    variable p : positive;
  begin
    assert p = 1 report "a positive starts at 1, not " & integer'image(p) severity failure;
    wait for 1 ns;
    if wrap and k = 7 then
      k <= 0;
    else
      k <= k + 1;
    end if;
  end process count;
end architecture a;
