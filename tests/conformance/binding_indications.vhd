-- vams: stop 5 ns
--
-- Binding indications as Ashenden's chapter on components and configurations writes them:
-- a configuration specification whose generic map gives the entity's extra generics
-- (`t_pd => 150 ps`) and passes the component's own (`width => width`); a binding to a
-- configuration declaration (`use configuration work.reg_slow ...`); and a component that
-- no entity binds (an unbound instance is legal, LRM 5.2.2: it elaborates as nothing, with a
-- warning), beside which the rest runs.

ENTITY delay_reg IS
  GENERIC ( t_pd : delay_length; width : positive );
  PORT ( d : IN bit_vector(0 TO width - 1); q : OUT bit_vector(0 TO width - 1) );
END ENTITY delay_reg;

ARCHITECTURE gate_level OF delay_reg IS
BEGIN
  q <= d AFTER t_pd;
END ARCHITECTURE gate_level;

CONFIGURATION reg_slow OF delay_reg IS
  FOR gate_level
  END FOR;
END CONFIGURATION reg_slow;

ENTITY tb_binding_indications IS
END ENTITY tb_binding_indications;

ARCHITECTURE structural OF tb_binding_indications IS
  COMPONENT reg IS
    GENERIC ( width : positive );
    PORT ( d : IN bit_vector(0 TO width - 1); q : OUT bit_vector(0 TO width - 1) );
  END COMPONENT reg;
  COMPONENT spare_part IS
    PORT ( a : IN bit );
  END COMPONENT spare_part;

  FOR fast : reg
    USE ENTITY work.delay_reg(gate_level)
    GENERIC MAP ( t_pd => 150 ps, width => width );
  FOR slow : reg
    USE CONFIGURATION work.reg_slow
    GENERIC MAP ( t_pd => 2 ns, width => width );

  SIGNAL a, b_fast, b_slow : bit_vector(0 TO 3);
BEGIN
  fast : COMPONENT reg GENERIC MAP (width => 4) PORT MAP (d => a, q => b_fast);
  slow : COMPONENT reg GENERIC MAP (width => 4) PORT MAP (d => a, q => b_slow);
  unused : COMPONENT spare_part PORT MAP (a => a(0));

  stimulus : PROCESS IS
  BEGIN
    a <= "1010";
    WAIT FOR 100 ps;
    ASSERT b_fast = "0000" REPORT "fast register too early" SEVERITY failure;
    WAIT FOR 100 ps;
    ASSERT b_fast = "1010" REPORT "fast register: 150 ps not applied" SEVERITY failure;
    ASSERT b_slow = "0000" REPORT "slow register too early" SEVERITY failure;
    WAIT FOR 2 ns;
    ASSERT b_slow = "1010" REPORT "slow register: 2 ns not applied" SEVERITY failure;
    WAIT;
  END PROCESS stimulus;
END ARCHITECTURE structural;
