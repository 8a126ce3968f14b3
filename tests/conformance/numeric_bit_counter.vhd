-- vams: stop 200 ns
--
-- A counter as the textbooks write it with ieee.numeric_bit: a `bit` clock, `rising_edge`
-- (numeric_bit's, on bit) clocking an unsigned register `count <= count + 1`, which wraps
-- from 15 to 0, a down counter on `falling_edge` that wraps below 0, a checker that counts
-- the clock edges itself and compares after each one, and a final check of both counters.
-- Clock period 10 ns from 5 ns: rising edges at 5, 15, ..., 195 ns (20 of them), falling
-- edges at 10, 20, ..., 190 ns (19).

LIBRARY ieee;  USE ieee.numeric_bit.ALL;

ENTITY numeric_bit_up_counter IS
  PORT ( clk : IN bit;  count : OUT unsigned(3 DOWNTO 0) );
END ENTITY numeric_bit_up_counter;

ARCHITECTURE rtl OF numeric_bit_up_counter IS
  SIGNAL q : unsigned(3 DOWNTO 0) := "0000";
BEGIN
  PROCESS (clk) IS
  BEGIN
    IF rising_edge(clk) THEN
      q <= q + 1;
    END IF;
  END PROCESS;
  count <= q;
END ARCHITECTURE rtl;

LIBRARY ieee;  USE ieee.numeric_bit.ALL;

ENTITY tb_numeric_bit_counter IS
END ENTITY tb_numeric_bit_counter;

ARCHITECTURE test OF tb_numeric_bit_counter IS
  SIGNAL clk : bit := '0';
  SIGNAL up : unsigned(3 DOWNTO 0);
  SIGNAL down : unsigned(7 DOWNTO 0) := X"03";
BEGIN
  clk <= NOT clk AFTER 5 ns;

  dut : ENTITY work.numeric_bit_up_counter PORT MAP ( clk => clk, count => up );

  down_counter : PROCESS (clk) IS
  BEGIN
    IF falling_edge(clk) THEN
      down <= down - 1;                                      -- 3, 2, 1, 0, 255, ...
    END IF;
  END PROCESS down_counter;

  -- Checks one delta after each edge has been counted (2 ns later), by its own tally.
  check : PROCESS IS
    VARIABLE rises, falls : natural := 0;
    VARIABLE expected : unsigned(7 DOWNTO 0);
  BEGIN
    WAIT UNTIL clk'EVENT;
    IF clk = '1' THEN
      ASSERT rising_edge(clk) AND NOT falling_edge(clk)
        REPORT "rising_edge on a 0 -> 1 event" SEVERITY error;
      rises := rises + 1;
    ELSE
      ASSERT falling_edge(clk) AND NOT rising_edge(clk)
        REPORT "falling_edge on a 1 -> 0 event" SEVERITY error;
      falls := falls + 1;
    END IF;
    WAIT FOR 2 ns;
    ASSERT NOT rising_edge(clk) AND NOT falling_edge(clk)
      REPORT "an edge 2 ns after the event" SEVERITY error;
    ASSERT to_integer(up) = rises MOD 16
      REPORT "up counter " & integer'IMAGE(to_integer(up)) & " after "
             & integer'IMAGE(rises) & " rising edges" SEVERITY error;
    expected := to_unsigned((3 - falls) MOD 256, 8);
    ASSERT down = expected
      REPORT "down counter " & integer'IMAGE(to_integer(down)) & " after "
             & integer'IMAGE(falls) & " falling edges" SEVERITY error;
  END PROCESS check;

  -- After the last edge: 20 rising edges (20 mod 16 = 4) and 19 falling ones (3 - 19 + 256).
  final : PROCESS IS
  BEGIN
    WAIT FOR 198 ns;
    ASSERT up = 4 AND down = 240 AND to_integer(down) = 240
      REPORT "counters at the end: " & integer'IMAGE(to_integer(up)) & ", "
             & integer'IMAGE(to_integer(down)) SEVERITY error;
    WAIT;
  END PROCESS final;
END ARCHITECTURE test;
