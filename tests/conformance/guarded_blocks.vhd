-- vams: stop 100 ns
--
-- Guarded blocks (LRM 9.1, 9.5): a block with a guard expression declares the implicit
-- signal GUARD, and `q <= GUARDED d;` assigns only while it is true, so the block is a
-- transparent latch (Ashenden's `latch`). GUARD can also be read by name inside the block.
-- A guarded selected assignment is skipped the same way.

ENTITY latch IS
  GENERIC (width : positive);
  PORT (enable : IN bit;
        d : IN bit_vector(0 TO width - 1);
        q : OUT bit_vector(0 TO width - 1));
END ENTITY latch;

ARCHITECTURE behavioral OF latch IS
BEGIN
  transfer_control : BLOCK (enable = '1') IS
  BEGIN
    q <= GUARDED d;
  END BLOCK transfer_control;
END ARCHITECTURE behavioral;

ENTITY tb_guarded_blocks IS
END ENTITY tb_guarded_blocks;

ARCHITECTURE test OF tb_guarded_blocks IS
  SIGNAL enable : bit := '0';
  SIGNAL d, q : bit_vector(0 TO 7);
  SIGNAL sel : integer := 0;
  SIGNAL code : bit_vector(1 DOWNTO 0);
  SIGNAL open_now : boolean := false;
BEGIN
  dut : ENTITY work.latch(behavioral)
    GENERIC MAP (width => 8)
    PORT MAP (enable => enable, d => d, q => q);

  coder : BLOCK (enable = '1' AND sel >= 0) IS
  BEGIN
    WITH sel SELECT
      code <= GUARDED "01" WHEN 1, "10" WHEN 2, "00" WHEN OTHERS;
    open_now <= GUARD;
  END BLOCK coder;

  stimulus : PROCESS IS
  BEGIN
    WAIT FOR 10 ns;
    d <= X"11";
    sel <= 1;
    WAIT FOR 10 ns;
    ASSERT q = X"00" REPORT "the latch passed data while disabled" SEVERITY error;
    ASSERT code = "00" REPORT "the coder assigned while its guard was false" SEVERITY error;
    ASSERT NOT open_now REPORT "GUARD read by name" SEVERITY error;
    enable <= '1';
    WAIT FOR 10 ns;
    ASSERT q = X"11" REPORT "transparent while enabled" SEVERITY error;
    ASSERT code = "01" REPORT "the coder follows sel" SEVERITY error;
    ASSERT open_now REPORT "GUARD true" SEVERITY error;
    d <= X"AA";
    WAIT FOR 10 ns;
    ASSERT q = X"AA" REPORT "follows d" SEVERITY error;
    enable <= '0';
    WAIT FOR 10 ns;
    d <= X"00";
    sel <= 2;
    WAIT FOR 10 ns;
    ASSERT q = X"AA" REPORT "holds while disabled" SEVERITY error;
    ASSERT code = "01" REPORT "the coder holds while disabled" SEVERITY error;
    WAIT;
  END PROCESS stimulus;
END ARCHITECTURE test;
