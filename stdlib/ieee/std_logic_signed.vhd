-- ieee.std_logic_signed: std_logic_vector read as signed (two's complement) numbers, the de-facto companion of
-- std_logic_arith, written for vams from its documented interface. Declarations only (see
-- std_logic_arith). The comparisons of two vectors are the predefined ones here: declaring
-- them again would make them ambiguous beside std_logic_1164's implicit ones.

library ieee;
use ieee.std_logic_1164.all;
use ieee.std_logic_arith.all;

package std_logic_signed is
  function "+" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector;
  function "+" (l : std_logic_vector; r : integer) return std_logic_vector;
  function "+" (l : integer; r : std_logic_vector) return std_logic_vector;
  function "+" (l : std_logic_vector; r : std_ulogic) return std_logic_vector;
  function "+" (l : std_ulogic; r : std_logic_vector) return std_logic_vector;
  function "-" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector;
  function "-" (l : std_logic_vector; r : integer) return std_logic_vector;
  function "-" (l : integer; r : std_logic_vector) return std_logic_vector;
  function "-" (l : std_logic_vector; r : std_ulogic) return std_logic_vector;
  function "-" (l : std_ulogic; r : std_logic_vector) return std_logic_vector;
  function "+" (l : std_logic_vector) return std_logic_vector;
  function "-" (l : std_logic_vector) return std_logic_vector;
  function "abs" (l : std_logic_vector) return std_logic_vector;
  function "*" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector;
  function "<" (l : std_logic_vector; r : integer) return boolean;
  function "<" (l : integer; r : std_logic_vector) return boolean;
  function "<=" (l : std_logic_vector; r : integer) return boolean;
  function "<=" (l : integer; r : std_logic_vector) return boolean;
  function ">" (l : std_logic_vector; r : integer) return boolean;
  function ">" (l : integer; r : std_logic_vector) return boolean;
  function ">=" (l : std_logic_vector; r : integer) return boolean;
  function ">=" (l : integer; r : std_logic_vector) return boolean;
  function "=" (l : std_logic_vector; r : integer) return boolean;
  function "=" (l : integer; r : std_logic_vector) return boolean;
  function "/=" (l : std_logic_vector; r : integer) return boolean;
  function "/=" (l : integer; r : std_logic_vector) return boolean;
  function shl (arg : std_logic_vector; count : std_logic_vector) return std_logic_vector;
  function shr (arg : std_logic_vector; count : std_logic_vector) return std_logic_vector;
  function conv_integer (arg : std_logic_vector) return integer;
end package std_logic_signed;
