-- vams: stop 100 ns
--
-- Aggregates of run-time values and aggregate targets (LRM 8.4, 9.5), as the textbooks write
-- a full adder: the inputs collected by `bit_vector'(a, b, c_in)`, the two outputs assigned
-- together by `(c_out, s) <= ...`, a stimulus vector spread over three signals by
-- `(a, b, c_in) <= stim(i);`, and a variable aggregate target reading its own targets
-- (`(hi, lo) := pair'(lo, hi);` swaps them).

ENTITY full_adder IS
  PORT ( a, b, c_in : IN BIT;  s, c_out : OUT BIT );
END ENTITY full_adder;

ARCHITECTURE truth_table OF full_adder IS
BEGIN
  WITH bit_vector'(a, b, c_in) SELECT
    (c_out, s) <= bit_vector'("00") WHEN "000",
                  bit_vector'("01") WHEN "001" | "010" | "100",
                  bit_vector'("10") WHEN "011" | "101" | "110",
                  bit_vector'("11") WHEN "111";
END ARCHITECTURE truth_table;

ENTITY tb_aggregate_targets IS
END ENTITY tb_aggregate_targets;

ARCHITECTURE test OF tb_aggregate_targets IS
  SIGNAL a, b, c_in, s, c_out : BIT;
  TYPE stimulus IS ARRAY (0 TO 7) OF bit_vector(0 TO 2);
  CONSTANT stim : stimulus := ("000", "001", "010", "011", "100", "101", "110", "111");
BEGIN
  dut : ENTITY work.full_adder(truth_table)
    PORT MAP ( a => a, b => b, c_in => c_in, s => s, c_out => c_out );

  apply : PROCESS IS
    VARIABLE ones : INTEGER;
  BEGIN
    FOR i IN stim'RANGE LOOP
      (a, b, c_in) <= stim(i);
      WAIT FOR 10 ns;
      ones := 0;
      FOR k IN 0 TO 2 LOOP
        IF stim(i)(k) = '1' THEN
          ones := ones + 1;
        END IF;
      END LOOP;
      ASSERT (c_out = '1') = (ones >= 2) REPORT "carry wrong" SEVERITY failure;
      ASSERT (s = '1') = (ones MOD 2 = 1) REPORT "sum wrong" SEVERITY failure;
    END LOOP;
    WAIT;
  END PROCESS apply;

  swap : PROCESS IS
    TYPE pair IS ARRAY (1 TO 2) OF INTEGER;
    VARIABLE hi, lo : INTEGER;
  BEGIN
    hi := 1;
    lo := 2;
    (hi, lo) := pair'(lo, hi);
    ASSERT hi = 2 AND lo = 1 REPORT "swap wrong" SEVERITY failure;
    WAIT;
  END PROCESS swap;
END ARCHITECTURE test;
