-- vams: stop 100 ns
--
-- A guarded assignment in a block that declares its own `guard` signal instead of a guard
-- expression (LRM 9.5: the guard is the signal named GUARD visible at the assignment), as
-- the guards-and-blocks chapter's CPU drives its address bus: the process clears `guard`
-- to release the bus, whose resolution function then sees no driver, and sets it again.

ENTITY tb_declared_guard IS
END ENTITY tb_declared_guard;

ARCHITECTURE test OF tb_declared_guard IS
  SUBTYPE word IS BIT_VECTOR(7 DOWNTO 0);
  TYPE word_vector IS ARRAY (NATURAL RANGE <>) OF word;

  FUNCTION resolve_word (drivers : word_vector) RETURN word IS
  BEGIN
    IF drivers'LENGTH > 0 THEN
      RETURN drivers(drivers'LEFT);
    ELSE
      RETURN X"FF";
    END IF;
  END FUNCTION resolve_word;

  SIGNAL address_bus : resolve_word word BUS;
BEGIN
  cpu : BLOCK IS
    SIGNAL guard : BOOLEAN := TRUE;
    SIGNAL internal_address : word := X"12";
  BEGIN
    address_bus <= GUARDED internal_address;

    controller : PROCESS IS
    BEGIN
      WAIT FOR 10 ns;
      ASSERT address_bus = X"12" REPORT "bus not driven while guard is true" SEVERITY ERROR;
      guard <= FALSE;
      WAIT FOR 10 ns;
      ASSERT address_bus = X"FF" REPORT "bus still driven with guard false" SEVERITY ERROR;
      internal_address <= X"34";
      guard <= TRUE;
      WAIT FOR 10 ns;
      ASSERT address_bus = X"34" REPORT "bus not driven again" SEVERITY ERROR;
      WAIT;
    END PROCESS controller;
  END BLOCK cpu;
END ARCHITECTURE test;
