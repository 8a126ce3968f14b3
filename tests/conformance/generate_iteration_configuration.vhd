-- vams: stop 10 ns
--
-- A configuration declaration that binds some iterations of a generate statement one way
-- and the others another (`for cells(0 to n - 2) ... end for; for cells(n - 1) ... end
-- for;`), as the textbooks' shift register with a stronger last stage does; the testbench
-- instantiates the configuration. The last cell drives 2, the others 1.

ENTITY cell IS
  PORT (y : OUT integer);
END ENTITY cell;

ARCHITECTURE normal_drive OF cell IS
BEGIN
  y <= 1;
END ARCHITECTURE normal_drive;

ARCHITECTURE high_drive OF cell IS
BEGIN
  y <= 2;
END ARCHITECTURE high_drive;

ENTITY cell_row IS
  GENERIC (n : positive := 4);
  PORT (ys : OUT integer_vector(0 TO 3));
END ENTITY cell_row;

ARCHITECTURE structure OF cell_row IS
  COMPONENT cell_c IS
    PORT (y : OUT integer);
  END COMPONENT cell_c;
BEGIN
  cells : FOR i IN 0 TO n - 1 GENERATE
    c : cell_c PORT MAP (y => ys(i));
  END GENERATE cells;
END ARCHITECTURE structure;

CONFIGURATION strong_last OF cell_row IS
  FOR structure
    FOR cells(0 TO n - 2)
      FOR c : cell_c
        USE ENTITY work.cell(normal_drive);
      END FOR;
    END FOR;
    FOR cells(n - 1)
      FOR c : cell_c
        USE ENTITY work.cell(high_drive);
      END FOR;
    END FOR;
  END FOR;
END CONFIGURATION strong_last;

ENTITY tb_generate_iteration_configuration IS
END ENTITY tb_generate_iteration_configuration;

ARCHITECTURE test OF tb_generate_iteration_configuration IS
  SIGNAL ys : integer_vector(0 TO 3);
BEGIN
  dut : CONFIGURATION work.strong_last PORT MAP (ys => ys);

  check : PROCESS IS
  BEGIN
    WAIT FOR 1 ns;
    FOR i IN 0 TO 2 LOOP
      ASSERT ys(i) = 1 REPORT "cell " & integer'image(i) & " drives " & integer'image(ys(i))
        SEVERITY error;
    END LOOP;
    ASSERT ys(3) = 2 REPORT "the last cell drives " & integer'image(ys(3)) SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
