-- vams: stop 10 ns
--
-- Shared variables of protected type passed as arguments (VHDL-2002): a procedure and an
-- impure function with a parameter of the protected type call its methods on the actual's
-- object; each call works on the shared variable it is given.

PACKAGE scoreboards IS
  TYPE scoreboard IS PROTECTED
    PROCEDURE add (points : integer);
    IMPURE FUNCTION total RETURN integer;
  END PROTECTED scoreboard;

  PROCEDURE add_twice (VARIABLE sb : INOUT scoreboard; points : integer);
  IMPURE FUNCTION total_of (VARIABLE sb : INOUT scoreboard) RETURN integer;
END PACKAGE scoreboards;

PACKAGE BODY scoreboards IS
  TYPE scoreboard IS PROTECTED BODY
    VARIABLE sum : integer := 0;
    PROCEDURE add (points : integer) IS
    BEGIN
      sum := sum + points;
    END PROCEDURE add;
    IMPURE FUNCTION total RETURN integer IS
    BEGIN
      RETURN sum;
    END FUNCTION total;
  END PROTECTED BODY scoreboard;

  PROCEDURE add_twice (VARIABLE sb : INOUT scoreboard; points : integer) IS
  BEGIN
    sb.add(points);
    sb.add(points);
  END PROCEDURE add_twice;

  IMPURE FUNCTION total_of (VARIABLE sb : INOUT scoreboard) RETURN integer IS
  BEGIN
    RETURN sb.total;
  END FUNCTION total_of;
END PACKAGE BODY scoreboards;

USE work.scoreboards.ALL;

ENTITY tb_protected_parameters IS
END ENTITY tb_protected_parameters;

ARCHITECTURE test OF tb_protected_parameters IS
  SHARED VARIABLE home, away : scoreboard;
BEGIN
  play : PROCESS IS
  BEGIN
    add_twice(home, 3);
    add_twice(away, 7);
    home.add(1);
    WAIT FOR 1 ns;
    ASSERT total_of(home) = 7 REPORT "home: " & integer'IMAGE(total_of(home)) SEVERITY failure;
    ASSERT total_of(away) = 14 REPORT "away: " & integer'IMAGE(total_of(away)) SEVERITY failure;
    WAIT;
  END PROCESS play;
END ARCHITECTURE test;
