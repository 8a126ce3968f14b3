-- IEEE.STD_LOGIC_TEXTIO for vams: std.textio's READ, WRITE, HREAD, HWRITE, OREAD and OWRITE
-- for std_ulogic, std_ulogic_vector and std_logic_vector (the de-facto package of VHDL-93
-- testbenches; VHDL-2008 moved these into std_logic_1164), written from its documented
-- interface. Implemented natively, as std.textio is: a value is written as its literals
-- ('U', 'X', '0', '1', 'Z', 'W', 'L', 'H', '-'), READ skips leading whitespace and reads
-- literals (any case), HWRITE writes X for a digit with a bit that is not 0 or 1.

library ieee;
use ieee.std_logic_1164.all;
use std.textio.all;

package std_logic_textio is

  procedure read (l : inout line; value : out std_ulogic;        good : out boolean);
  procedure read (l : inout line; value : out std_ulogic);
  procedure read (l : inout line; value : out std_ulogic_vector; good : out boolean);
  procedure read (l : inout line; value : out std_ulogic_vector);
  procedure read (l : inout line; value : out std_logic_vector;  good : out boolean);
  procedure read (l : inout line; value : out std_logic_vector);

  procedure write (l : inout line; value : in std_ulogic;
                   justified : in side := right; field : in width := 0);
  procedure write (l : inout line; value : in std_ulogic_vector;
                   justified : in side := right; field : in width := 0);
  procedure write (l : inout line; value : in std_logic_vector;
                   justified : in side := right; field : in width := 0);

  procedure hread (l : inout line; value : out std_ulogic_vector; good : out boolean);
  procedure hread (l : inout line; value : out std_ulogic_vector);
  procedure hread (l : inout line; value : out std_logic_vector;  good : out boolean);
  procedure hread (l : inout line; value : out std_logic_vector);

  procedure hwrite (l : inout line; value : in std_ulogic_vector;
                    justified : in side := right; field : in width := 0);
  procedure hwrite (l : inout line; value : in std_logic_vector;
                    justified : in side := right; field : in width := 0);

  procedure oread (l : inout line; value : out std_ulogic_vector; good : out boolean);
  procedure oread (l : inout line; value : out std_ulogic_vector);
  procedure oread (l : inout line; value : out std_logic_vector;  good : out boolean);
  procedure oread (l : inout line; value : out std_logic_vector);

  procedure owrite (l : inout line; value : in std_ulogic_vector;
                    justified : in side := right; field : in width := 0);
  procedure owrite (l : inout line; value : in std_logic_vector;
                    justified : in side := right; field : in width := 0);

end package std_logic_textio;
