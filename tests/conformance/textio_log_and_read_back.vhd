-- A testbench logs to a file with std.textio, then reads the file back and checks it.
-- vams: stop 1 ns
library ieee;
use std.textio.all;

entity tb_textio_log is
end entity tb_textio_log;

architecture test of tb_textio_log is
  file log : text;
begin
  process
    variable l : line;
    variable status : file_open_status;
    variable n : integer;
    variable x : real;
    variable t : time;
    variable b : bit_vector(7 downto 0);
    variable word : string(1 to 5);
    variable ok : boolean;
    variable count : natural := 0;
  begin
    file_open(status, log, "tb_textio_log.txt", write_mode);
    assert status = open_ok report "cannot open the log" severity failure;
    for k in 1 to 3 loop
      write(l, string'("step"));
      write(l, k, right, 3);
      write(l, ' ');
      write(l, real(k) * 0.5, left, 0, 2);
      write(l, ' ');
      write(l, k * 10 ns);
      write(l, ' ');
      hwrite(l, bit_vector'(X"A5"));
      writeline(log, l);
    end loop;
    file_close(log);

    file_open(log, "tb_textio_log.txt", read_mode);
    while not endfile(log) loop
      readline(log, l);
      read(l, word);
      assert word = "step " report "word: " & word severity error;
      read(l, n);
      read(l, x);
      read(l, t);
      hread(l, b, ok);
      assert ok and b = X"A5" report "hread failed" severity error;
      count := count + 1;
      assert n = count report "n = " & integer'image(n) severity error;
      assert x = real(count) * 0.5 report "x = " & real'image(x) severity error;
      assert t = count * 10 ns report "t = " & time'image(t) severity error;
      read(l, n, ok);
      assert not ok report "read past the line's end succeeded" severity error;
      deallocate(l);
    end loop;
    file_close(log);
    assert count = 3 report "lines read: " & integer'image(count) severity error;
    report "textio round trip done";
    wait;
  end process;
end architecture test;
