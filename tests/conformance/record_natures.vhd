-- vams: stop 1 ms
--
-- Record natures and record quantities (LRM 1076.1 4.1.2, Ashenden's chapter on composite
-- data): a bus nature with a scalar and an array field, terminals of it (also as a port),
-- branch quantities between a bus terminal and the reference (record quantities, read by
-- field and element, and through aliases), a branch on one field's terminal, and a free
-- quantity of a record type. Each field is a resistive load on a source, so every value has
-- a closed form.

LIBRARY ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;

PACKAGE bus_natures IS
  NATURE electrical_bus IS RECORD
    strobe : electrical;
    databus : electrical_vector(0 TO 3);
  END RECORD;
  TYPE operating_point IS RECORD
    gain : real;
    offsets : real_vector(1 TO 2);
  END RECORD;
END PACKAGE bus_natures;

LIBRARY ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;
USE work.bus_natures.ALL;

-- A 100 Ohm load on every line of a bus.
ENTITY bus_load IS
  PORT (TERMINAL lines : electrical_bus);
END ENTITY bus_load;

ARCHITECTURE ideal OF bus_load IS
  QUANTITY v ACROSS i THROUGH lines TO ground;
BEGIN
  i.strobe == v.strobe / 100.0;
  loads : FOR k IN 0 TO 3 GENERATE
    i.databus(k) == v.databus(k) / 100.0;
  END GENERATE loads;
END ARCHITECTURE ideal;

LIBRARY ieee_proposed;
USE ieee_proposed.electrical_systems.ALL;
USE work.bus_natures.ALL;

ENTITY tb_record_natures IS
END ENTITY tb_record_natures;

ARCHITECTURE test OF tb_record_natures IS
  TERMINAL ebus : electrical_bus;
  QUANTITY bus_voltages ACROSS bus_currents THROUGH ebus TO electrical_ref;
  ALIAS e_strobe IS bus_voltages.strobe;
  ALIAS e_data IS bus_voltages.databus;
  QUANTITY v_src ACROSS i_src THROUGH ebus.strobe;
  QUANTITY op : operating_point;
BEGIN
  load : ENTITY work.bus_load PORT MAP (lines => ebus);

  -- Sources: 2 V on the strobe line, 1, 2, 3, 4 V on the data lines.
  v_src == 2.0;
  bus_currents.strobe == 0.0;
  sources : FOR k IN 0 TO 3 GENERATE
    e_data(k) == real(k + 1);
  END GENERATE sources;

  op.gain == 2.0 * e_strobe;
  op.offsets(1) == bus_voltages.databus(1) - 1.0;
  op.offsets(2) == -op.offsets(1);

  check : PROCESS IS
  BEGIN
    WAIT FOR 0.5 ms;
    ASSERT e_strobe = 2.0 REPORT "strobe voltage" SEVERITY failure;
    -- The load's 20 mA come from the source (a through quantity leaving ebus.strobe).
    ASSERT abs(i_src + 0.02) < 1.0e-12 REPORT "strobe source current" SEVERITY failure;
    FOR k IN 0 TO 3 LOOP
      ASSERT abs(bus_voltages.databus(k) - real(k + 1)) < 1.0e-12
        REPORT "data line voltage" SEVERITY failure;
      -- The source of line k drives its load: -(k + 1) V / 100 Ohm through the branch.
      ASSERT abs(bus_currents.databus(k) + real(k + 1) / 100.0) < 1.0e-12
        REPORT "data line current" SEVERITY failure;
    END LOOP;
    ASSERT op.gain = 4.0 AND op.offsets(1) = 1.0 AND op.offsets(2) = -1.0
      REPORT "record quantity" SEVERITY failure;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
