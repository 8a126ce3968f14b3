-- A linked list of integers in a testbench: an incomplete type, access values, `new`,
-- vams: stop 1 ns
-- `.all`, field selection through the access value, `null` and `deallocate`.
entity tb_linked_list is
end entity tb_linked_list;

architecture test of tb_linked_list is
begin
  process
    type cell;
    type link is access cell;
    type cell is record
      value : integer;
      next_cell : link;
    end record cell;
    variable head, p, tail : link := null;
    variable sum, count : integer := 0;
  begin
    -- Append 1 to 5 at the tail.
    for k in 1 to 5 loop
      p := new cell'(value => k, next_cell => null);
      if head = null then
        head := p;
      else
        tail.next_cell := p;
      end if;
      tail := p;
    end loop;
    -- Double every value in place, through a walking pointer.
    p := head;
    while p /= null loop
      p.value := 2 * p.value;
      p := p.next_cell;
    end loop;
    p := head;
    while p /= null loop
      sum := sum + p.all.value;
      count := count + 1;
      p := p.next_cell;
    end loop;
    assert count = 5 report "count = " & integer'image(count) severity error;
    assert sum = 30 report "sum = " & integer'image(sum) severity error;
    assert head.next_cell.next_cell.value = 6 report "third value" severity error;
    -- Free the list from the head.
    while head /= null loop
      p := head;
      head := head.next_cell;
      deallocate(p);
      assert p = null report "deallocate leaves null" severity error;
    end loop;
    report "linked list done";
    wait;
  end process;
end architecture test;
