-- vams: stop 10 ms
--
-- failure: reports a note at 1 ms, an error at 2 ms (printed; `vams run` still exits 0 for
-- it), and a failure at 3 ms, which ends the run: `vams run` exits 1.

entity failure is
end entity failure;

architecture behavioral of failure is
begin
  process
  begin
    wait for 1 ms;
    report "starting" severity note;
    wait for 1 ms;
    assert false report "something is off" severity error;
    wait for 1 ms;
    assert false report "giving up" severity failure;
    wait;
  end process;
end architecture behavioral;
