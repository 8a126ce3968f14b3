-- vams: stop 20 ns
--
-- 'last_value of signals driven element by element (LRM 14.1): each process of a generate
-- drives one element, elements change at different times and some transactions change
-- nothing; at every event the whole array's 'last_value is its value before that event,
-- also for elements that changed at an earlier event (the kernel updates such a signal in
-- place and keeps 'last_value through the elements that changed). Expected values from GHDL.

ENTITY tb_element_last_value IS
END ENTITY tb_element_last_value;

ARCHITECTURE test OF tb_element_last_value IS
  TYPE bits_table IS ARRAY (natural RANGE <>) OF bit_vector(0 TO 3);
  TYPE ints_table IS ARRAY (natural RANGE <>) OF integer_vector(0 TO 2);
  CONSTANT q_values : bits_table := ("1100", "1110", "0111", "0011", "0001", "0000", "1000");
  CONSTANT q_lasts : bits_table := ("0000", "1100", "1110", "0111", "0011", "0001", "0000");
  CONSTANT r_values : ints_table := ((5, 0, 0), (0, 0, 0), (0, 6, 0), (0, -1, 0), (0, -1, 7),
                                     (0, -1, -2));
  CONSTANT r_lasts : ints_table := ((0, 0, 0), (5, 0, 0), (0, 0, 0), (0, 6, 0), (0, -1, 0),
                                    (0, -1, 7));
  SIGNAL q : bit_vector(0 TO 3) := "0000";
  SIGNAL r : integer_vector(0 TO 2) := (OTHERS => 0);
  SIGNAL q_events, r_events : natural := 0;
BEGIN
  first : PROCESS IS
  BEGIN
    WAIT FOR 1 ns;
    q(0) <= '1';
    WAIT FOR 2 ns;
    q(0) <= '0';
    WAIT FOR 1 ns;
    q(0) <= '0';
    WAIT FOR 5 ns;
    q(0) <= '1';
    WAIT;
  END PROCESS first;

  others_q : FOR i IN 1 TO 3 GENERATE
    stage : PROCESS IS
    BEGIN
      WAIT FOR i * 1 ns;
      q(i) <= '1';
      WAIT FOR 3 ns;
      q(i) <= NOT q(i);
      WAIT FOR 1 ns;
      q(i) <= q(i);
      WAIT;
    END PROCESS stage;
  END GENERATE others_q;

  each_r : FOR i IN 0 TO 2 GENERATE
    stage : PROCESS IS
    BEGIN
      WAIT FOR (i + 1) * 2 ns;
      r(i) <= i + 5;
      WAIT FOR 1 ns;
      r(i) <= -i;
      WAIT;
    END PROCESS stage;
  END GENERATE each_r;

  watch_q : PROCESS IS
    VARIABLE k : natural := 0;
  BEGIN
    WAIT ON q;
    ASSERT q = q_values(k) REPORT "q at event " & integer'image(k) SEVERITY failure;
    ASSERT q'last_value = q_lasts(k)
      REPORT "q'last_value at event " & integer'image(k) SEVERITY failure;
    k := k + 1;
    q_events <= k;
  END PROCESS watch_q;

  watch_r : PROCESS IS
    VARIABLE k : natural := 0;
  BEGIN
    WAIT ON r;
    ASSERT r = r_values(k) REPORT "r at event " & integer'image(k) SEVERITY failure;
    ASSERT r'last_value = r_lasts(k)
      REPORT "r'last_value at event " & integer'image(k) SEVERITY failure;
    k := k + 1;
    r_events <= k;
  END PROCESS watch_r;

  done : PROCESS IS
  BEGIN
    WAIT FOR 15 ns;
    ASSERT q_events = q_values'length REPORT "events of q" SEVERITY failure;
    ASSERT r_events = r_values'length REPORT "events of r" SEVERITY failure;
    WAIT;
  END PROCESS done;
END ARCHITECTURE test;
