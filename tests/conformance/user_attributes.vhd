-- vams: stop 1 ns
--
-- User-defined attributes (LRM 4.4, 5.1, 6.6), as Ashenden's chapter on attributes and
-- groups uses them: values given to a signal, a port, an architecture, a statement label,
-- enumeration literals and overloaded functions named with their signatures, `others` and
-- `all`, a specification without a signature decorating every overload, and a record value
-- read by field.

ENTITY attributed_cell IS
  PORT ( enable : IN bit );
  ATTRIBUTE pin_number : positive;
  ATTRIBUTE pin_number OF enable : SIGNAL IS 14;
END ENTITY attributed_cell;

ARCHITECTURE std_cell OF attributed_cell IS
  ATTRIBUTE cell_name : string;
  ATTRIBUTE cell_name OF std_cell : ARCHITECTURE IS "DFF_SR_QQNN";
BEGIN
  check : PROCESS IS
  BEGIN
    ASSERT enable'pin_number = 14 REPORT "pin_number" SEVERITY failure;
    ASSERT std_cell'cell_name = "DFF_SR_QQNN" REPORT "cell_name" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE std_cell;

ENTITY tb_user_attributes IS
END ENTITY tb_user_attributes;

ARCHITECTURE test OF tb_user_attributes IS
  SIGNAL clk1, clk2, test_enable, en : bit;
  ATTRIBUTE max_wire_delay : delay_length;
  ATTRIBUTE max_wire_delay OF clk1, clk2 : SIGNAL IS 100 ps;
  ATTRIBUTE max_wire_delay OF OTHERS : SIGNAL IS 200 ps;

  TYPE controller_state IS (idle, active, fail_safe);
  TYPE load_level IS (idle, busy, overloaded);
  SUBTYPE encoding_type IS bit_vector(1 DOWNTO 0);
  ATTRIBUTE encoding : encoding_type;
  ATTRIBUTE encoding OF idle [RETURN controller_state] : LITERAL IS b"00";
  ATTRIBUTE encoding OF idle [RETURN load_level] : LITERAL IS b"11";
  ATTRIBUTE encoding OF active : LITERAL IS b"01";

  FUNCTION increment (x : integer) RETURN integer IS
  BEGIN
    RETURN x + 1;
  END FUNCTION increment;
  FUNCTION increment (x : real) RETURN real IS
  BEGIN
    RETURN x + 1.0;
  END FUNCTION increment;
  TYPE built_in_type IS (int_incr, real_incr);
  ATTRIBUTE built_in : built_in_type;
  ATTRIBUTE built_in OF increment [integer RETURN integer] : FUNCTION IS int_incr;
  ATTRIBUTE built_in OF increment [real RETURN real] : FUNCTION IS real_incr;
  ATTRIBUTE purity : string;
  ATTRIBUTE purity OF increment : FUNCTION IS "pure";

  TYPE length IS RANGE 0 TO integer'high
    UNITS nm;
      um = 1000 nm;
    END UNITS length;
  TYPE coordinate IS RECORD
    x, y : length;
  END RECORD coordinate;
  ATTRIBUTE cell_position : coordinate;
  ATTRIBUTE cell_position OF the_fpu : LABEL IS (540 um, 1200 um);
BEGIN
  the_fpu : BLOCK IS
  BEGIN
  END BLOCK the_fpu;

  cell : ENTITY work.attributed_cell PORT MAP (en);

  check : PROCESS IS
  BEGIN
    ASSERT clk1'max_wire_delay = 100 ps AND clk2'max_wire_delay = 100 ps
      REPORT "named signals" SEVERITY failure;
    ASSERT test_enable'max_wire_delay = 200 ps AND en'max_wire_delay = 200 ps
      REPORT "others" SEVERITY failure;
    ASSERT idle [RETURN controller_state]'encoding = b"00"
      REPORT "idle of controller_state" SEVERITY failure;
    ASSERT idle [RETURN load_level] ' encoding = b"11"
      REPORT "idle of load_level" SEVERITY failure;
    ASSERT active'encoding = b"01" REPORT "active" SEVERITY failure;
    ASSERT increment [integer RETURN integer]'built_in = int_incr
      REPORT "integer increment" SEVERITY failure;
    ASSERT increment [real RETURN real]'built_in = real_incr
      REPORT "real increment" SEVERITY failure;
    ASSERT increment [real RETURN real]'purity = "pure"
      AND increment [integer RETURN integer]'purity = "pure"
      REPORT "every overload" SEVERITY failure;
    ASSERT the_fpu'cell_position.y = 1200 um REPORT "label" SEVERITY failure;
    ASSERT length'image(the_fpu'cell_position.x) = "540000 nm"
      REPORT "record field" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
