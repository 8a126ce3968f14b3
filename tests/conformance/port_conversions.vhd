-- vams: stop 60 ns
--
-- Conversion functions and type conversions in port maps (LRM 4.3.2.2): the actual of an
-- `in` port converted (`clk => to_b(clk_sl)`), the formal of an `out` port converted
-- (`to_bool(q) => q_bool`, `real(n) => count_real`), a conversion of a constant. The
-- converted value changes in the same simulation cycle as its source, with no delta cycle
-- between them: a flip-flop whose
-- clock comes through a conversion still samples its data before the clock edge's process
-- changes it (one delta cycle later). The values agree with GHDL's.

ENTITY conv_flipflop IS
    PORT (clk, d : IN bit; q : OUT bit; edges : OUT integer);
END ENTITY conv_flipflop;

ARCHITECTURE behav OF conv_flipflop IS
BEGIN
    sample : PROCESS (clk) IS
        VARIABLE n : integer := 0;
    BEGIN
        IF clk'EVENT AND clk = '1' THEN
            q <= d;
            n := n + 1;
            edges <= n;
        END IF;
    END PROCESS sample;
END ARCHITECTURE behav;

LIBRARY ieee;
USE ieee.std_logic_1164.ALL;

ENTITY tb_port_conversions IS
END ENTITY tb_port_conversions;

ARCHITECTURE checked OF tb_port_conversions IS
    FUNCTION to_b (x : std_ulogic) RETURN bit IS
    BEGIN
        RETURN to_bit(x);
    END FUNCTION to_b;
    FUNCTION to_bool (b : bit) RETURN boolean IS
    BEGIN
        RETURN b = '1';
    END FUNCTION to_bool;
    SIGNAL clk_sl : std_ulogic := '0';
    SIGNAL d : bit := '0';
    SIGNAL q_bool : boolean;
    SIGNAL count_real : real;
    SIGNAL q_high : boolean;
BEGIN
    ff : ENTITY work.conv_flipflop
        PORT MAP (clk => to_b(clk_sl), d => d, to_bool(q) => q_bool, real(edges) => count_real);

    -- A conversion of a static value is a constant actual.
    high : ENTITY work.conv_flipflop
        PORT MAP (clk => to_b(clk_sl), d => to_b('1'), to_bool(q) => q_high, edges => OPEN);

    clk_sl <= NOT clk_sl AFTER 5 ns;

    -- The data toggles one delta cycle after each rising edge: the flip-flop, clocked in
    -- the edge's own cycle, samples the value from before.
    data : PROCESS IS
    BEGIN
        WAIT UNTIL clk_sl = '1';
        d <= NOT d;
    END PROCESS data;

    check : PROCESS IS
    BEGIN
        ASSERT count_real = real(integer'LEFT) REPORT "initial count" SEVERITY error;
        ASSERT NOT q_bool REPORT "initial q" SEVERITY error;
        WAIT FOR 6 ns;
        -- First edge at 5 ns: d was '0'.
        ASSERT count_real = 1.0 REPORT "one edge" SEVERITY error;
        ASSERT NOT q_bool REPORT "q after the first edge" SEVERITY error;
        ASSERT q_high REPORT "the constant actual" SEVERITY error;
        WAIT FOR 10 ns;
        -- Second edge at 15 ns: d was '1' (toggled after the first).
        ASSERT count_real = 2.0 REPORT "two edges" SEVERITY error;
        ASSERT q_bool REPORT "q after the second edge" SEVERITY error;
        WAIT FOR 10 ns;
        ASSERT count_real = 3.0 AND NOT q_bool REPORT "third edge" SEVERITY error;
        WAIT;
    END PROCESS check;

    watch : PROCESS (q_bool) IS
    BEGIN
        REPORT "q_bool " & boolean'IMAGE(q_bool);
    END PROCESS watch;
END ARCHITECTURE checked;
