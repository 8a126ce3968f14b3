-- A slice of a signal whose bounds depend on a variable, where a static signal name is
-- needed (a sensitivity list, LRM 6.1): an error. (As an assignment target it runs.)
entity t is
end entity t;

architecture a of t is
  signal b : bit_vector(7 downto 0);
begin
  process
    variable n : integer := 2;
  begin
    b(n + 1 downto n - 1) <= "111";
    wait on b(n + 1 downto n - 1);
  end process;
end architecture a;
