-- A function that loads a table from a file named by its parameter (the ROM-initialisation
-- idiom): the file object declared in the function is opened at each call, from the start.
-- The testbench writes the file first.
-- vams: stop 1 ns
use std.textio.all;

entity tb_file_in_function is
end entity tb_file_in_function;

architecture test of tb_file_in_function is
  type table is array (0 to 3) of integer;

  impure function load (name : string) return table is
    file data : text open read_mode is name;
    variable l : line;
    variable t : table := (others => 0);
  begin
    for k in t'range loop
      readline(data, l);
      read(l, t(k));
    end loop;
    return t;
  end function load;
begin
  process
    file out_file : text open write_mode is "tb_file_in_function.txt";
    variable l : line;
    variable first, second : table;
  begin
    for k in 0 to 3 loop
      write(l, 10 * k + 1);
      writeline(out_file, l);
    end loop;
    file_close(out_file);
    first := load("tb_file_in_function.txt");
    second := load("tb_file_in_function.txt");
    assert first = (1, 11, 21, 31) report "first load differs" severity error;
    assert second = first report "the second call did not read from the start" severity error;
    report "file in function done";
    wait;
  end process;
end architecture test;
