-- vams: stop 2 ms
--
-- A procedural that assigns the elements of a quantity array in a loop, as the book's
-- `multiple_opamp` does (generics/multiple_opamp): each element is one equation,
-- v_out(i) == gain(i) * v_in(i). The whole array is also assigned at once, and one element
-- read back after it is assigned.

LIBRARY ieee, ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;
USE ieee.math_real.ALL;

ENTITY scaled_copies IS
  GENERIC ( size : POSITIVE;
            gains : real_vector );
  PORT ( TERMINAL inputs, outputs : electrical_vector(1 TO size) );
END ENTITY scaled_copies;

ARCHITECTURE ideal OF scaled_copies IS
  QUANTITY v_in ACROSS i_in THROUGH inputs TO electrical_ref;
  QUANTITY v_out ACROSS outputs TO electrical_ref;
  ALIAS gains_alias : real_vector(1 TO size) IS gains;
BEGIN
  amplify : PROCEDURAL IS
  BEGIN
    FOR index IN 1 TO size LOOP
      v_out(index) := v_in(index) * gains_alias(index);
    END LOOP;
  END PROCEDURAL amplify;
END ARCHITECTURE ideal;

LIBRARY ieee, ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;
USE ieee.math_real.ALL;

ENTITY tb_procedural_array IS
END ENTITY tb_procedural_array;

ARCHITECTURE test OF tb_procedural_array IS
  TERMINAL a, b : electrical_vector(1 TO 3);
  QUANTITY va ACROSS a TO electrical_ref;
  QUANTITY vb ACROSS b TO electrical_ref;
  QUANTITY sorted : real_vector(0 TO 1);
  QUANTITY last : REAL;
BEGIN
  u : ENTITY work.scaled_copies
    GENERIC MAP (3, (1.0, 2.0, -3.0))
    PORT MAP (a, b);
  va(1) == 1.0;
  va(2) == 2.0;
  va(3) == sin(1.0e3 * NOW);

  -- The smaller and the larger of va(2) and va(3), then the last element read back.
  PROCEDURAL IS
  BEGIN
    sorted := (va(2), va(3));
    IF va(3) < va(2) THEN
      sorted := (va(3), va(2));
    END IF;
    last := sorted(1) + 1.0;
  END PROCEDURAL;

  check : PROCESS IS
  BEGIN
    FOR k IN 1 TO 4 LOOP
      WAIT FOR 0.5 ms;
      ASSERT abs(vb(1) - 1.0) < 1.0e-9 AND abs(vb(2) - 4.0) < 1.0e-9
        REPORT "constant elements are wrong" SEVERITY failure;
      ASSERT abs(vb(3) + 3.0 * va(3)) < 1.0e-9
        REPORT "the third element is not -3 * va(3)" SEVERITY failure;
      ASSERT abs(va(3) - sin(1.0e3 * NOW)) < 1.0e-3
        REPORT "the source is off" SEVERITY failure;
      ASSERT abs(sorted(0) - va(3)) < 1.0e-9 AND abs(sorted(1) - 2.0) < 1.0e-9
        AND abs(last - 3.0) < 1.0e-9
        REPORT "the whole-array assignment is wrong" SEVERITY failure;
    END LOOP;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
