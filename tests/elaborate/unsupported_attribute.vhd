entity t is end;
architecture a of t is
  signal s : real := 0.0;
begin
  process
  begin
    report s'instance_name;
    wait;
  end process;
end;
