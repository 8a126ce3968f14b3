-- vams: stop 1 ms
--
-- A block statement with its own generic and port clauses and maps, as in the textbooks'
-- structural examples: inside the block the formal names stand for the actual signals, and
-- the generic takes its mapped value.

ENTITY tb_block_ports IS
END ENTITY tb_block_ports;

ARCHITECTURE test OF tb_block_ports IS
  SIGNAL source : INTEGER := 0;
  SIGNAL doubled : INTEGER := 0;
BEGIN
  scale : BLOCK IS
    GENERIC (factor : INTEGER := 1);
    GENERIC MAP (factor => 2);
    PORT (a : IN INTEGER; y : OUT INTEGER);
    PORT MAP (a => source, y => doubled);
  BEGIN
    y <= factor * a;
  END BLOCK scale;

  stimulus : PROCESS
  BEGIN
    WAIT FOR 10 us;
    source <= 21;
    WAIT FOR 10 us;
    ASSERT doubled = 42 REPORT "doubled = " & INTEGER'IMAGE(doubled) SEVERITY ERROR;
    WAIT;
  END PROCESS stimulus;
END ARCHITECTURE test;
