entity t is end;
architecture a of t is
  signal n : integer := 0;
begin
  p : process
  begin
    if n then
      n <= 1;
    end if;
    wait;
  end process;
end;
