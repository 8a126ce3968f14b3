-- vams: stop 10 ns
--
-- An alias of a type (LRM 4.3.3.2) denotes the type and declares aliases of its enumeration
-- literals and predefined operators right after it, so a design unit that aliases a
-- package's type without a `use` clause can write its literals and compare them, as
-- Ashenden's `alias status_type is work.system_types.system_status;` does.

PACKAGE system_types IS
  TYPE system_status IS (idle, active, overloaded);
END PACKAGE system_types;

ENTITY tb_type_aliases IS
END ENTITY tb_type_aliases;

ARCHITECTURE test OF tb_type_aliases IS
  ALIAS status_type IS work.system_types.system_status;
BEGIN
  check : PROCESS IS
    VARIABLE status : status_type := idle;
  BEGIN
    ASSERT status = idle REPORT "the literals are visible" SEVERITY error;
    status := overloaded;
    ASSERT status > active AND status_type'pos(status) = 2
      REPORT "the predefined operators and attributes apply" SEVERITY error;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
