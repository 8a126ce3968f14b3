library ieee_proposed; use ieee_proposed.electrical_systems.all;
entity t is end;
architecture a of t is
  terminal n : electrical;
  quantity v across i through n;
begin
  v == 1.0;
  process
  begin
    report real'image(v'across);
    wait;
  end process;
end;
