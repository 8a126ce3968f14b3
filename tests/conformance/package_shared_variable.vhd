-- vams: stop 10 ns
--
-- A shared variable of a protected type declared in a package, the type's body in the
-- package body (the layout of the book's cache instrumentation): two processes increment
-- it, a third reads the total. The values agree with GHDL's.

PACKAGE hit_counters IS
    TYPE counter IS PROTECTED
        PROCEDURE increment (by : integer);
        IMPURE FUNCTION value RETURN integer;
    END PROTECTED counter;
    SHARED VARIABLE hits : counter;
END PACKAGE hit_counters;

PACKAGE BODY hit_counters IS
    TYPE counter IS PROTECTED BODY
        VARIABLE count : integer := 0;
        PROCEDURE increment (by : integer) IS
        BEGIN
            count := count + by;
        END PROCEDURE increment;
        IMPURE FUNCTION value RETURN integer IS
        BEGIN
            RETURN count;
        END FUNCTION value;
    END PROTECTED BODY counter;
END PACKAGE BODY hit_counters;

USE work.hit_counters.ALL;

ENTITY tb_package_shared_variable IS
END ENTITY tb_package_shared_variable;

ARCHITECTURE checked OF tb_package_shared_variable IS
BEGIN
    first : PROCESS IS
    BEGIN
        hits.increment(2);
        WAIT;
    END PROCESS first;

    second : PROCESS IS
    BEGIN
        WAIT FOR 1 ns;
        hits.increment(3);
        WAIT;
    END PROCESS second;

    check : PROCESS IS
    BEGIN
        WAIT FOR 2 ns;
        ASSERT hits.value = 5 REPORT "hits is " & integer'IMAGE(hits.value) SEVERITY error;
        WAIT;
    END PROCESS check;
END ARCHITECTURE checked;
