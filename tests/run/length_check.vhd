-- vams: stop 20 ns
--
-- Array values whose length is known only at run time, assigned to targets of known length
-- (LRM 8.4, 8.5): each `-g which=K` makes one of them wrong at 5 ns, where the run stops
-- naming the target and both lengths; `which=0` runs to the end with every length right.
entity length_check is
  generic (which : natural := 0);
end entity length_check;

architecture a of length_check is
  signal s : bit_vector(3 downto 0);
  subtype nibble is bit_vector(3 downto 0);
  constant pattern : bit_vector(7 downto 0) := "10110101";

  -- The low n + 1 bits of pattern: a result whose length is known only at run time.
  function low (n : natural) return bit_vector is
  begin
    return pattern(n downto 0);
  end function low;

  function as_nibble (n : natural) return nibble is
  begin
    return pattern(n downto 0);
  end function as_nibble;

  procedure copy (n : natural; o : out bit_vector) is
    variable r : bit_vector(3 downto 0) := pattern(n downto 0);
  begin
    o := r;
  end procedure copy;
begin
  p : process is
    variable v : bit_vector(7 downto 0);
    variable w : bit_vector(3 downto 0);
    variable n : natural := 3;
  begin
    wait for 5 ns;
    if which /= 0 then
      n := 2;
    end if;
    case which is
      when 0 | 1 => v := low(n) & low(n);
      when 2 => s <= low(n) after 3 ns;
      when 3 => v(7 downto 4) := low(n);
      when 4 => copy(n, w);
      when 5 => w := as_nibble(n);
      when 6 => s(n downto 0) <= low(n + 1);
      when others => null;
    end case;
    wait for 10 ns;
    assert s = "0000" report "s is not assigned" severity failure;
    wait;
  end process p;
end architecture a;
