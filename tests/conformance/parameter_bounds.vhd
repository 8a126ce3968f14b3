-- vams: stop 10 ns
--
-- Subprograms whose local arrays take their bounds from parameters, as textbook conversion
-- functions and stimulus procedures are written (Ashenden's `natural_to_bv` and
-- `all_possible_values`): `variable result : bit_vector(0 to length - 1)` with `length`
-- given at each call, and `bv'length` of an unconstrained signal parameter.

ENTITY tb_parameter_bounds IS
END ENTITY tb_parameter_bounds;

ARCHITECTURE test OF tb_parameter_bounds IS
  FUNCTION natural_to_bv (nat : IN natural; length : IN natural) RETURN bit_vector IS
    VARIABLE temp : natural := nat;
    VARIABLE result : bit_vector(0 TO length - 1);
  BEGIN
    FOR index IN result'REVERSE_RANGE LOOP
      result(index) := bit'VAL(temp REM 2);
      temp := temp / 2;
    END LOOP;
    RETURN result;
  END FUNCTION natural_to_bv;

  PROCEDURE all_possible_values (SIGNAL bv : OUT bit_vector;
                                 delay_between_values : IN delay_length) IS
  BEGIN
    bv <= natural_to_bv(0, bv'LENGTH);
    FOR value IN 1 TO 2**bv'LENGTH - 1 LOOP
      WAIT FOR delay_between_values;
      bv <= natural_to_bv(value, bv'LENGTH);
    END LOOP;
  END PROCEDURE all_possible_values;

  SIGNAL three : bit_vector(2 DOWNTO 0);
  SIGNAL count : natural := 0;
BEGIN
  stimulus : PROCESS IS
  BEGIN
    all_possible_values(three, 1 ns);
    WAIT;
  END PROCESS stimulus;

  counter : PROCESS (three) IS
  BEGIN
    count <= count + 1;
  END PROCESS counter;

  check : PROCESS IS
    VARIABLE five : bit_vector(0 TO 3);
  BEGIN
    five := natural_to_bv(5, 4);
    ASSERT five = "0101" REPORT "natural_to_bv(5, 4)" SEVERITY failure;
    ASSERT natural_to_bv(5, 6) = "000101" REPORT "natural_to_bv(5, 6)" SEVERITY failure;
    WAIT FOR 3500 ps;
    ASSERT three = "011" REPORT "three after 3.5 ns: " & integer'IMAGE(count) SEVERITY failure;
    WAIT FOR 5 ns;
    ASSERT three = "111" AND count = 8
      REPORT "the procedure stops at 111 after 8 values" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
