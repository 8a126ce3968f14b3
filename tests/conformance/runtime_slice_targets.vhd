-- vams: stop 100 ns
--
-- Signal assignments to slices whose bounds are known only at run time: a window moving
-- along a descending vector, an ascending one filled from a loop, a waveform of two
-- elements, and a slice of a port associated with a slice of the actual (its own bounds
-- differ from the signal's). Each element of the slice gets its own transaction; the
-- values agree with GHDL's.

ENTITY runtime_slice_filler IS
    PORT (q : OUT bit_vector(1 TO 4));
END ENTITY runtime_slice_filler;

ARCHITECTURE behav OF runtime_slice_filler IS
BEGIN
    fill : PROCESS IS
        VARIABLE n : natural := 2;
    BEGIN
        q <= "0000";
        WAIT FOR 1 ns;
        q(1 TO n) <= (OTHERS => '1');
        WAIT FOR 1 ns;
        q(n + 1 TO 4) <= "01";
        WAIT;
    END PROCESS fill;
END ARCHITECTURE behav;

ENTITY tb_runtime_slice_targets IS
END ENTITY tb_runtime_slice_targets;

ARCHITECTURE checked OF tb_runtime_slice_targets IS
    SIGNAL window : bit_vector(7 DOWNTO 0) := (OTHERS => '0');
    SIGNAL ramp : bit_vector(0 TO 5) := (OTHERS => '0');
    SIGNAL pulse : bit_vector(3 DOWNTO 0) := (OTHERS => '0');
    SIGNAL wide : bit_vector(0 TO 9) := (OTHERS => '0');
BEGIN
    u : ENTITY work.runtime_slice_filler PORT MAP (q => wide(3 TO 6));

    move : PROCESS IS
    BEGIN
        FOR i IN 0 TO 6 LOOP
            window <= (OTHERS => '0');
            window(i + 1 DOWNTO i) <= "11";
            WAIT FOR 1 ns;
            ASSERT window = (bit_vector'("00000011") SLL i)
                REPORT "window at " & integer'image(i) SEVERITY error;
        END LOOP;
        FOR k IN ramp'RANGE LOOP
            ramp(0 TO k) <= (OTHERS => '1');
            WAIT FOR 1 ns;
            ASSERT ramp(k) = '1' AND (k = 5 OR ramp(k + 1) = '0')
                REPORT "ramp at " & integer'image(k) SEVERITY error;
        END LOOP;
        WAIT;
    END PROCESS move;

    waves : PROCESS IS
        VARIABLE hi : integer := 2;
    BEGIN
        pulse(hi DOWNTO 1) <= "11", "10" AFTER 5 ns, "00" AFTER 10 ns;
        WAIT FOR 1 ns;
        ASSERT pulse = "0110" REPORT "pulse at 1 ns" SEVERITY error;
        WAIT FOR 5 ns;
        ASSERT pulse = "0100" REPORT "pulse at 6 ns" SEVERITY error;
        WAIT FOR 5 ns;
        ASSERT pulse = "0000" REPORT "pulse at 11 ns" SEVERITY error;
        WAIT;
    END PROCESS waves;

    ports : PROCESS IS
    BEGIN
        WAIT FOR 3 ns;
        ASSERT wide = "0001101000" REPORT "the port's slices" SEVERITY error;
        WAIT;
    END PROCESS ports;
END ARCHITECTURE checked;
