-- A function that runs for minutes (two billion interpreted iterations) at 1 ns: Ctrl-C must
-- stop it in the middle, not when it returns.
entity long_function is end;
architecture a of long_function is
  function inner (n : integer) return integer is
    variable acc : integer := 0;
  begin
    for j in 1 to n loop
      acc := (acc + j) mod 1000;
    end loop;
    return acc;
  end function;
  function spin (n : integer) return integer is
    variable acc : integer := 0;
  begin
    for k in 1 to n loop
      acc := (acc + inner(1000)) mod 1000;
    end loop;
    return acc;
  end function;
  signal s : integer := 0;
begin
  process begin
    wait for 1 ns;
    s <= spin(2000000);
    wait;
  end process;
end;
