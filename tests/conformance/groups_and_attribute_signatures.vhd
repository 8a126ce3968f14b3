-- vams: stop 5 ms
--
-- Declarations that carry information for other tools and must not stop a simulation
-- (Ashenden's chapters on attributes and groups, and on analog modelling): a subnature with
-- its own tolerance groups (LRM 1076.1 4.8), a group template and a group of signals
-- (LRM 4.6, 4.7), and attribute specifications whose entity designators carry signatures,
-- name operator symbols or character literals (LRM 5.1); `'tolerance` of a subtype and of a
-- free quantity is its tolerance group. The circuit is the textbook RC low
-- pass on terminals of the subnature: v(t) = 1 - exp(-t / RC), RC = 1 ms.

LIBRARY ieee_proposed;  USE ieee_proposed.electrical_systems.ALL;
LIBRARY ieee;  USE ieee.math_real.ALL;

ENTITY tb_groups_and_attribute_signatures IS
END ENTITY tb_groups_and_attribute_signatures;

ARCHITECTURE test OF tb_groups_and_attribute_signatures IS
  SUBNATURE accurate_electrical IS electrical
    TOLERANCE "accurate_voltage" ACROSS "accurate_current" THROUGH;

  TERMINAL inp, outp : accurate_electrical;
  QUANTITY vin ACROSS iin THROUGH inp;
  QUANTITY vr ACROSS ir THROUGH inp TO outp;
  QUANTITY vc ACROSS ic THROUGH outp;
  SUBTYPE coarse_current IS current TOLERANCE "coarse_current";
  QUANTITY probe : coarse_current;

  SIGNAL clk_a, clk_b : bit;
  GROUP signal_pair IS (SIGNAL, SIGNAL);
  GROUP clock_pair : signal_pair (clk_a, clk_b);
  ATTRIBUTE max_skew : time;
  ATTRIBUTE max_skew OF clock_pair : GROUP IS 100 ps;

  FUNCTION clip (x : integer) RETURN integer IS
  BEGIN
    RETURN x;
  END FUNCTION clip;
  FUNCTION clip (x : real) RETURN real IS
  BEGIN
    RETURN x;
  END FUNCTION clip;
  ATTRIBUTE built_in : string;
  ATTRIBUTE built_in OF clip [integer RETURN integer] : FUNCTION IS "int_limit";
  ATTRIBUTE built_in OF clip [real RETURN real] : FUNCTION IS "real_limit";
  ATTRIBUTE built_in OF "+" [bit_vector, bit_vector RETURN bit_vector] : FUNCTION IS "bv_add";

  TYPE level IS ('L', 'H');
  ATTRIBUTE encoding : string;
  ATTRIBUTE encoding OF 'H' [RETURN level] : LITERAL IS "1";
BEGIN
  vin == 1.0;
  probe == ic;
  vr == 1.0e3 * ir;
  IF DOMAIN = QUIESCENT_DOMAIN USE
    vc == 0.0;
  ELSE
    ic == 1.0e-6 * vc'DOT;
  END USE;

  check : PROCESS
  BEGIN
    WAIT FOR 2 ms;
    ASSERT ABS(vc - (1.0 - EXP(-2.0))) < 5.0e-3
      REPORT "vc(2 ms) = " & REAL'IMAGE(vc) SEVERITY ERROR;
    ASSERT clip(3) = 3 AND clip(2.5) = 2.5 REPORT "overloads" SEVERITY ERROR;
    ASSERT voltage'TOLERANCE = "DEFAULT_VOLTAGE" AND probe'TOLERANCE = "coarse_current"
      REPORT "tolerance groups" SEVERITY ERROR;
    WAIT;
  END PROCESS check;
END ARCHITECTURE test;
