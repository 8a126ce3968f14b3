-- A signal slice target whose bounds depend on a variable: not supported yet, said so.
entity t is
end entity t;

architecture a of t is
  signal b : bit_vector(7 downto 0);
begin
  process
    variable n : integer := 2;
  begin
    b(n + 1 downto n - 1) <= "111";
    wait;
  end process;
end architecture a;
