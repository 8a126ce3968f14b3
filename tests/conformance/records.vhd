-- Record types: aggregates (positional, named, `|`, `others`), field selection of
-- constants, variables, signals and function results, field targets, arrays of records,
-- record ports and parameters, events on one field.
-- vams: stop 100 ns

package clock_types is
  type time_stamp is record
    seconds : integer range 0 to 59;
    minutes : integer range 0 to 59;
    hours : integer range 0 to 23;
  end record time_stamp;
  constant midday : time_stamp := (hours => 12, minutes => 0, seconds => 0);
  function tick (t : time_stamp) return time_stamp;
end package clock_types;

package body clock_types is
  function tick (t : time_stamp) return time_stamp is
    variable r : time_stamp := t;
  begin
    if r.seconds = 59 then
      r.seconds := 0;
      r.minutes := (r.minutes + 1) mod 60;
    else
      r.seconds := r.seconds + 1;
    end if;
    return r;
  end function tick;
end package body clock_types;

use work.clock_types.all;

entity clock is
  port (clk : in bit; now_time : out time_stamp);
end entity clock;

architecture behav of clock is
begin
  process (clk) is
    variable t : time_stamp := (others => 0);
  begin
    if clk = '1' then
      t := tick(t);
      now_time <= t;
    end if;
  end process;
end architecture behav;

use work.clock_types.all;

entity tb_records is
end entity tb_records;

architecture test of tb_records is
  type opcodes is (add, sub, addu, nop);
  type instruction is record
    opcode : opcodes;
    source_reg1, source_reg2, dest_reg : natural range 0 to 31;
    displacement : integer;
  end record instruction;
  type program is array (0 to 3) of instruction;
  type pair is record
    x : real;
    stamp : time_stamp;
    flags : bit_vector(3 downto 0);
  end record;
  constant nop_instr : instruction :=
    (opcode => nop, source_reg1 | source_reg2 | dest_reg => 0, displacement => 0);
  signal clk : bit := '0';
  signal stamp : time_stamp;
  signal s : time_stamp := (1, 2, 3);
  signal p : pair;
  signal minute_events : natural := 0;
begin
  counter : entity work.clock port map (clk => clk, now_time => stamp);
  clk <= not clk after 5 ns when now < 50 ns;

  -- A process sensitive to one field wakes on that field's events only.
  count_minutes : process (s.minutes) is
  begin
    if now > 0 ns then
      minute_events <= minute_events + 1;
    end if;
  end process;

  check : process is
    variable sample_time, current_time : time_stamp;
    variable latest : time_stamp := (others => 0);
    variable q : pair;
    variable prog : program := (others => nop_instr);
    variable h : integer;
    variable regs : pair;
    alias flags is regs.flags;
    alias low_flags is regs.flags(1 downto 0);
    alias hour is regs.stamp.hours;
  begin
    -- Aliases of fields, slices of fields and nested fields read and write the record.
    hour := 9;
    low_flags := "11";
    flags(3) := '1';
    assert regs.stamp.hours = 9 and regs.flags = "1011" and hour = 9 and low_flags = "11";
    -- Defaults are each field's 'left, constants fold.
    assert latest = (0, 0, 0) and q.stamp = (0, 0, 0) and q.flags = "0000";
    assert midday.hours = 12 and midday = (0, 0, 12);
    assert nop_instr.opcode = nop and nop_instr.dest_reg = 0;
    current_time := (30, 15, 2);
    sample_time := current_time;
    h := sample_time.hours;
    assert h = 2;
    current_time.seconds := 79 mod 60;
    assert current_time = (19, 15, 2);
    assert current_time /= sample_time;
    -- Nested field and element targets.
    q.stamp.hours := 5;
    q.flags(2) := '1';
    assert q.stamp = (0, 0, 5) and q.flags = "0100";
    prog(1).opcode := addu;
    prog(1).displacement := -4;
    assert prog(1).opcode = addu and prog(1).displacement = -4 and prog(2) = nop_instr;
    assert tick((59, 7, 1)) = (0, 8, 1) and tick(midday).seconds = 1;
    -- Signal fields: one field assigned, the others keep their values.
    s.minutes <= 7;
    p <= (1.5, midday, "1010");
    wait for 1 ns;
    assert s = (1, 7, 3) report "one field assigned";
    assert p.x = 1.5 and p.stamp.hours = 12 and p.flags(3) = '1';
    assert s.minutes'last_event = 1 ns and s.hours'last_event > 1 ns;
    s.hours <= 4;
    wait for 1 ns;
    assert minute_events = 0 report "the minutes process woke on another field";
    s.minutes <= 8;
    wait for 1 ns;
    assert minute_events = 1 and s = (1, 8, 4) report "the minutes process slept";
    -- A record port: five rising edges by 50 ns.
    wait for 60 ns;
    assert stamp = (5, 0, 0) report "clock: " & integer'image(stamp.seconds);
    wait;
  end process;
end architecture test;
