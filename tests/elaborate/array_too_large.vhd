entity t is end;
architecture a of t is
  type grid is array (natural range <>, natural range <>) of real;
begin
  process
    -- Each dimension is small; their product is not.
    variable g : grid(1 to 10000, 1 to 10000);
  begin
    wait;
  end process;
end;
