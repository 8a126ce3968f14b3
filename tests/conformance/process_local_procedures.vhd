-- Procedures and functions declared in a process use the process's variables (LRM
-- 2.1.1.1): a testbench's helpers that count checks and failures.
-- vams: stop 10 ns

entity tb_process_local_procedures is
end entity tb_process_local_procedures;

architecture test of tb_process_local_procedures is
  signal dut_out : integer := 0;
begin
  dut_out <= 3 after 1 ns, 5 after 2 ns;

  stimulus : process is
    variable checks, failures : natural := 0;
    variable last : integer := -1;
    constant threshold : integer := 4;

    procedure check (expected : integer) is
    begin
      checks := checks + 1;
      if dut_out /= expected then
        failures := failures + 1;
      end if;
      last := dut_out;
    end procedure check;

    procedure check_twice (expected : integer) is
    begin
      check(expected);
      check(expected);
    end procedure check_twice;

    impure function over_limit return boolean is
    begin
      return last > threshold;
    end function over_limit;
  begin
    check(0);
    wait for 1.5 ns;
    check(3);
    check(4);           -- fails
    assert checks = 3 and failures = 1 and last = 3;
    assert not over_limit;
    wait for 1 ns;
    check_twice(5);
    assert checks = 5 and failures = 1 and last = 5 and over_limit;
    wait;
  end process stimulus;
end architecture test;
