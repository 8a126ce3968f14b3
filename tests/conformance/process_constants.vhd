-- vams: stop 10 ns
--
-- Constants of a process whose values are known only when it starts (LRM 12.3.1.4): one
-- computed by an impure function from a signal's initial value, one from a function of a
-- static argument that bounds a variable declared after it. The values agree with GHDL's.

ENTITY tb_process_constants IS
END ENTITY tb_process_constants;

ARCHITECTURE checked OF tb_process_constants IS
    SIGNAL s : integer := 7;
    FUNCTION width (bits : natural) RETURN natural IS
    BEGIN
        RETURN 2 * bits;
    END FUNCTION width;
BEGIN
    check : PROCESS IS
        IMPURE FUNCTION doubled RETURN integer IS
        BEGIN
            RETURN 2 * s;
        END FUNCTION doubled;
        CONSTANT start : integer := doubled;
        CONSTANT n : natural := width(2);
        VARIABLE v : bit_vector(0 TO n - 1);
    BEGIN
        ASSERT start = 14 REPORT "start is " & integer'IMAGE(start) SEVERITY error;
        ASSERT v'LENGTH = 4 REPORT "v'length is " & integer'IMAGE(v'LENGTH) SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
