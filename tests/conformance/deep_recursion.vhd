-- Ordinary recursion: a function 1000 calls deep and a recursive procedure walking a linked
-- list of 1000 cells (the command line allows 10 000 nested calls).
-- vams: stop 1 ns
entity tb_deep_recursion is
end entity tb_deep_recursion;

architecture test of tb_deep_recursion is
  -- n! modulo a prime, by recursion.
  function factorial_mod (n : natural) return natural is
  begin
    if n = 0 then
      return 1;
    end if;
    return (n * factorial_mod(n - 1)) mod 1000003;
  end function factorial_mod;

  function iterative_mod (n : natural) return natural is
    variable r : natural := 1;
  begin
    for k in 1 to n loop
      r := (k * r) mod 1000003;
    end loop;
    return r;
  end function iterative_mod;
begin
  process
    type cell;
    type link is access cell;
    type cell is record
      value : integer;
      next_cell : link;
    end record cell;
    variable head : link := null;
    variable total : integer := 0;

    procedure sum (p : in link; acc : inout integer) is
    begin
      if p /= null then
        acc := acc + p.value;
        sum(p.next_cell, acc);
      end if;
    end procedure sum;
  begin
    assert factorial_mod(1000) = iterative_mod(1000)
      report "factorial_mod(1000) = " & integer'image(factorial_mod(1000)) severity error;
    for k in 1 to 1000 loop
      head := new cell'(k, head);
    end loop;
    sum(head, total);
    assert total = 500500 report "sum = " & integer'image(total) severity error;
    report "deep recursion done";
    wait;
  end process;
end architecture test;
