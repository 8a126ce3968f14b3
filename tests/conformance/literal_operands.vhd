-- vams: stop 1 ns
--
-- Operands whose type only the operator decides, as the textbooks write them in
-- assertions: a bit-string literal shifted (`B"10001010" sll 3`, a bit_vector, the one
-- predefined shift operand it can be) and two elements joined (`'a' & 'b'` is a string,
-- `'1' & '0'` a bit_vector). Folded where constant, evaluated at run time otherwise.

ENTITY tb_literal_operands IS
END ENTITY tb_literal_operands;

ARCHITECTURE test OF tb_literal_operands IS
BEGIN
  PROCESS
    VARIABLE c : CHARACTER := 'b';
    VARIABLE b : BIT := '0';
    VARIABLE n : INTEGER := 2;
  BEGIN
    ASSERT B"10001010" SLL 3 = B"01010000" REPORT "sll 3" SEVERITY ERROR;
    ASSERT B"10001010" SLL -2 = B"00100010" REPORT "sll -2" SEVERITY ERROR;
    ASSERT B"10010111" SRA 2 = B"11100101" REPORT "sra 2" SEVERITY ERROR;
    ASSERT B"10010111" ROL n = B"01011110" REPORT "rol n" SEVERITY ERROR;
    ASSERT X"0F" SRL n = X"03" REPORT "srl n" SEVERITY ERROR;
    ASSERT 'a' & 'b' = "ab" REPORT "'a' & 'b'" SEVERITY ERROR;
    ASSERT 'a' & c = "ab" REPORT "'a' & c" SEVERITY ERROR;
    ASSERT ('1' & b) = BIT_VECTOR'("10") REPORT "'1' & b" SEVERITY ERROR;
    WAIT;
  END PROCESS;
END ARCHITECTURE test;
