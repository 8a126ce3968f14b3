-- vams: stop 40 ns
--
-- Reduced from the GHDL differential's seed 867: a waveform of two elements whose values
-- are compound expressions, assigned five times over in one loop at 12.9 ns (each inertial
-- assignment replaces the last). The second element changes s3 at 12.9 + 10.5 = 23.4 ns
-- exactly (LRM 8.4.1: each element's time is the current time plus its delay). GHDL 2.0's
-- mcode backend puts this event at 23 385 920 fs when the second value is
-- `(s1(3) nand s2) xnor ('0' xor s1(2))` (23.4 ns with a literal there): a GHDL defect, so
-- this disagreement of the differential stays, and this test holds vams to the LRM.

entity tb_waveform_element_times is end;
architecture t of tb_waveform_element_times is
  subtype bv4 is bit_vector(3 downto 0);
  signal s1 : bv4 := "0000";
  signal s2 : bit := '0';
  signal s3 : bit := '1';
  signal events : natural := 0;
begin
  watch : process (s3)
  begin
    if now > 0 ns then
      assert now = 23400 ps and s3 = '0'
        report "s3 changed to " & bit'image(s3) & " at " & time'image(now)
          & "; expected '0' at 23400 ps" severity error;
      events <= events + 1;
    end if;
  end process;

  drive : process
  begin
    wait for 12900 ps;
    for i in 0 to 4 loop
      s3 <= ((bit'('1') and s1(0)) nand (s2 or s2)) after 5400 ps,
            ((s1(((boolean'pos(true) * 7)) mod 4) nand s2) xnor (bit'('0') xor s1(2))) after 10500 ps;
    end loop;
    wait for 20 ns;
    assert events = 1 report "s3 changed " & integer'image(events) & " time(s); expected once"
      severity error;
    wait;
  end process;
end architecture t;
