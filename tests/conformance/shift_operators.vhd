-- vams: stop 10 ns
--
-- The predefined shift and rotate operators on bit_vector (LRM 7.2.3): sll and srl fill with
-- '0', sla with the rightmost element, sra with the leftmost, rol and ror rotate; a negative
-- count shifts the other way, a count past the length shifts everything out. The logical
-- operators apply element by element to bit_vector, and `not` too. An operator is called by
-- its symbol like a function, `"+"(a, b)`, as Ashenden's packages do.

ENTITY tb_shift_operators IS
END ENTITY tb_shift_operators;

ARCHITECTURE test OF tb_shift_operators IS
  SIGNAL reg : bit_vector(7 DOWNTO 0) := "10010110";

  FUNCTION add_sat (a, b : integer) RETURN integer IS
  BEGIN
    RETURN "+"(a, b);
  END FUNCTION add_sat;
BEGIN
  check : PROCESS IS
    VARIABLE v : bit_vector(0 TO 3) := "1011";
  BEGIN
    ASSERT (v SLL 1) = "0110" REPORT "sll" SEVERITY error;
    ASSERT (v SRL 1) = "0101" REPORT "srl" SEVERITY error;
    ASSERT (v SLA 1) = "0111" REPORT "sla keeps the rightmost bit" SEVERITY error;
    ASSERT (v SRA 1) = "1101" REPORT "sra keeps the leftmost bit" SEVERITY error;
    ASSERT (v ROL 1) = "0111" REPORT "rol" SEVERITY error;
    ASSERT (v ROR 1) = "1101" REPORT "ror" SEVERITY error;
    ASSERT (v SLL -1) = "0101" REPORT "sll by -1 is srl by 1" SEVERITY error;
    ASSERT (v ROL 5) = "0111" REPORT "rol wraps" SEVERITY error;
    ASSERT (v SLL 9) = "0000" REPORT "sll past the length" SEVERITY error;
    ASSERT (reg SRL 4) = "00001001" REPORT "srl of a signal" SEVERITY error;
    ASSERT (NOT v) = "0100" REPORT "not" SEVERITY error;
    ASSERT (v AND "0110") = "0010" REPORT "and" SEVERITY error;
    ASSERT (v XOR "1111") = "0100" REPORT "xor" SEVERITY error;
    ASSERT "+"(2, 3) = 5 AND add_sat(4, 5) = 9 REPORT "operator symbol calls" SEVERITY error;
    reg <= reg ROL 1;
    WAIT FOR 1 ns;
    ASSERT reg = "00101101" REPORT "rol assigned to a signal" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
