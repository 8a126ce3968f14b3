-- A procedure declared in a process, called with a process variable as its `inout` actual:
-- the result must land in the variable, although the body could also reach that variable by
-- name (vams passed such variables in and back as hidden parameters, and that copy won).
-- vams: stop 1 ns
entity tb_inout_of_a_visible_variable is
end entity tb_inout_of_a_visible_variable;

architecture test of tb_inout_of_a_visible_variable is
begin
  process
    variable total : integer := 0;
    variable calls : natural := 0;

    procedure add (n : in integer; acc : inout integer) is
    begin
      acc := acc + n;
      calls := calls + 1;  -- the body does use a process variable of its own
    end procedure add;

    procedure count_down (n : in integer; acc : inout integer) is
    begin
      if n > 0 then
        acc := acc + n;
        count_down(n - 1, acc);
      end if;
    end procedure count_down;
  begin
    add(5, total);
    assert total = 5 report "add: total = " & integer'image(total) severity error;
    assert calls = 1 report "add: calls = " & integer'image(calls) severity error;
    total := 0;
    count_down(3, total);
    assert total = 6 report "count_down: total = " & integer'image(total) severity error;
    report "inout of a visible variable done";
    wait;
  end process;
end architecture test;
