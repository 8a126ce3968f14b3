-- ieee.std_logic_unsigned: std_logic_vector read as unsigned numbers, the de-facto
-- companion of std_logic_arith, written for vams from its documented interface. Each function
-- copies its vectors into std_logic_arith's unsigned (element by element: vams converts arrays
-- only within one type) and applies std_logic_arith's operator, whose result lengths and
-- metavalue rules hold here too. The comparisons of two vectors are the predefined ones here:
-- declaring them again would make them ambiguous beside std_logic_1164's implicit ones.

library ieee;
use ieee.std_logic_1164.all;
use ieee.std_logic_arith.all;

package std_logic_unsigned is
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
end package std_logic_unsigned;

package body std_logic_unsigned is

  -- Element-by-element copies between std_logic_vector and std_logic_arith's types.
  function u (a : std_logic_vector) return unsigned is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    variable result : unsigned(a'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := av(i);
    end loop;
    return result;
  end function u;

  function v (a : unsigned) return std_logic_vector is
    alias av : unsigned(a'length - 1 downto 0) is a;
    variable result : std_logic_vector(a'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := av(i);
    end loop;
    return result;
  end function v;

  function "+" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    lv := u(l);
    rv := u(r);
    return lv + rv;
  end function "+";

  function "+" (l : std_logic_vector; r : integer) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv + r;
  end function "+";

  function "+" (l : integer; r : std_logic_vector) return std_logic_vector is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l + rv;
  end function "+";

  function "+" (l : std_logic_vector; r : std_ulogic) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv + r;
  end function "+";

  function "+" (l : std_ulogic; r : std_logic_vector) return std_logic_vector is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l + rv;
  end function "+";

  function "-" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    lv := u(l);
    rv := u(r);
    return lv - rv;
  end function "-";

  function "-" (l : std_logic_vector; r : integer) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv - r;
  end function "-";

  function "-" (l : integer; r : std_logic_vector) return std_logic_vector is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l - rv;
  end function "-";

  function "-" (l : std_logic_vector; r : std_ulogic) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv - r;
  end function "-";

  function "-" (l : std_ulogic; r : std_logic_vector) return std_logic_vector is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l - rv;
  end function "-";

  function "+" (l : std_logic_vector) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return "+"(lv);
  end function "+";

  function "*" (l : std_logic_vector; r : std_logic_vector) return std_logic_vector is
    variable lv : unsigned(l'length - 1 downto 0);
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    lv := u(l);
    rv := u(r);
    return lv * rv;
  end function "*";

  function "<" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv < r;
  end function "<";

  function "<" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l < rv;
  end function "<";

  function "<=" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv <= r;
  end function "<=";

  function "<=" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l <= rv;
  end function "<=";

  function ">" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv > r;
  end function ">";

  function ">" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l > rv;
  end function ">";

  function ">=" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv >= r;
  end function ">=";

  function ">=" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l >= rv;
  end function ">=";

  function "=" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv = r;
  end function "=";

  function "=" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l = rv;
  end function "=";

  function "/=" (l : std_logic_vector; r : integer) return boolean is
    variable lv : unsigned(l'length - 1 downto 0);
  begin
    lv := u(l);
    return lv /= r;
  end function "/=";

  function "/=" (l : integer; r : std_logic_vector) return boolean is
    variable rv : unsigned(r'length - 1 downto 0);
  begin
    rv := u(r);
    return l /= rv;
  end function "/=";

  function shl (arg : std_logic_vector; count : std_logic_vector) return std_logic_vector is
    variable av : unsigned(arg'length - 1 downto 0);
    variable cv : unsigned(count'length - 1 downto 0);
    variable result : unsigned(arg'length - 1 downto 0);
  begin
    av := u(arg);
    cv := u(count);
    result := shl(av, cv);
    return v(result);
  end function shl;

  function shr (arg : std_logic_vector; count : std_logic_vector) return std_logic_vector is
    variable av : unsigned(arg'length - 1 downto 0);
    variable cv : unsigned(count'length - 1 downto 0);
    variable result : unsigned(arg'length - 1 downto 0);
  begin
    av := u(arg);
    cv := u(count);
    result := shr(av, cv);
    return v(result);
  end function shr;

  function conv_integer (arg : std_logic_vector) return integer is
    variable av : unsigned(arg'length - 1 downto 0);
  begin
    av := u(arg);
    return conv_integer(av);
  end function conv_integer;
end package body std_logic_unsigned;
