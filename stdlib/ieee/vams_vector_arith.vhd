-- ieee.vams_vector_arith: the arithmetic of std_logic vectors read as numbers, shared by the
-- bodies of ieee.numeric_std and ieee.std_logic_arith (both run as user code). A vams-internal
-- package: models do not use it. Vectors are taken as (length-1 downto 0); a metavalue in an
-- operand gives an all-'X' result.

library ieee;
use ieee.std_logic_1164.all;

package vams_vector_arith is
  function xs (like : std_logic_vector) return std_logic_vector;
  function unknown (a : std_logic_vector) return boolean;
  function clean (a : std_logic_vector) return std_logic_vector;
  function extend (a : std_logic_vector; signed_fill : boolean; like : std_logic_vector)
    return std_logic_vector;
  function l_in (x : std_ulogic; like : std_logic_vector) return std_logic_vector;
  function i_in (x : integer; like : std_logic_vector) return std_logic_vector;
  function add (a, b : std_logic_vector; carry : natural) return std_logic_vector;
  function sum (a, b : std_logic_vector) return std_logic_vector;
  function diff (a, b : std_logic_vector) return std_logic_vector;
  function mul (a, b : std_logic_vector) return std_logic_vector;
  function neg (a : std_logic_vector) return std_logic_vector;
  function absv (a : std_logic_vector) return std_logic_vector;
  function cmp (a, b : std_logic_vector) return integer;
  function count_of (a : std_logic_vector; most : natural) return integer;
  function uint (a : std_logic_vector) return integer;
  function sint (a : std_logic_vector) return integer;
  function vbuild (a : std_logic_vector; fill : std_logic; size : natural)
    return std_logic_vector;
  function fill_of (a : std_logic_vector; signed_fill : boolean) return std_logic;
end package vams_vector_arith;

package body vams_vector_arith is

  -- n elements 'X', n the length of like.
  function xs (like : std_logic_vector) return std_logic_vector is
    variable result : std_logic_vector(like'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := 'X';
    end loop;
    return result;
  end function xs;

  -- True when a (a normalised operand) is unknown, that is all 'X'.
  function unknown (a : std_logic_vector) return boolean is
  begin
    for i in a'range loop
      if a(i) = 'X' then
        return true;
      end if;
    end loop;
    return false;
  end function unknown;

  -- a as a number: (a'length-1 downto 0) of '0'/'1', or all 'X' if a holds a metavalue.
  function clean (a : std_logic_vector) return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    variable result : std_logic_vector(a'length - 1 downto 0);
  begin
    for i in result'range loop
      if av(i) = '0' or av(i) = 'L' then
        result(i) := '0';
      elsif av(i) = '1' or av(i) = 'H' then
        result(i) := '1';
      else
        return xs(a);
      end if;
    end loop;
    return result;
  end function clean;

  -- a (normalised) zero-extended (fill '0') or sign-extended (fill its top bit) to the length
  -- of like, or its low bits; all 'X' stays all 'X'.
  function extend (a : std_logic_vector; signed_fill : boolean; like : std_logic_vector)
    return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    variable result : std_logic_vector(like'length - 1 downto 0);
    variable fill : std_logic := '0';
  begin
    if unknown(a) then
      return xs(like);
    end if;
    if signed_fill and a'length > 0 then
      fill := av(a'length - 1);
    end if;
    for i in result'range loop
      if i < a'length then
        result(i) := av(i);
      else
        result(i) := fill;
      end if;
    end loop;
    return result;
  end function extend;

  function l_in (x : std_ulogic; like : std_logic_vector) return std_logic_vector is
    variable a : std_logic_vector(0 downto 0);
  begin
    a(0) := x;
    a := clean(a);
    return extend(a, false, like);
  end function l_in;

  function i_in (x : integer; like : std_logic_vector) return std_logic_vector is
    variable result : std_logic_vector(like'length - 1 downto 0);
    variable v : integer := x;
  begin
    for i in 0 to like'length - 1 loop
      if v mod 2 = 1 then
        result(i) := '1';
        v := (v - 1) / 2;
      else
        result(i) := '0';
        v := v / 2;
      end if;
    end loop;
    return result;
  end function i_in;

  -- a + b + carry in a'length bits (a and b normalised, of equal lengths).
  function add (a, b : std_logic_vector; carry : natural) return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    alias bv : std_logic_vector(b'length - 1 downto 0) is b;
    variable result : std_logic_vector(a'length - 1 downto 0);
    variable c : natural := carry;
    variable s : natural;
  begin
    if unknown(a) or unknown(b) then
      return xs(a);
    end if;
    for i in 0 to a'length - 1 loop
      s := c;
      if av(i) = '1' then
        s := s + 1;
      end if;
      if bv(i) = '1' then
        s := s + 1;
      end if;
      if s mod 2 = 1 then
        result(i) := '1';
      else
        result(i) := '0';
      end if;
      c := s / 2;
    end loop;
    return result;
  end function add;

  function sum (a, b : std_logic_vector) return std_logic_vector is
  begin
    return add(a, b, 0);
  end function sum;

  -- a - b: a + not b + 1.
  function diff (a, b : std_logic_vector) return std_logic_vector is
    alias bv : std_logic_vector(b'length - 1 downto 0) is b;
    variable nb : std_logic_vector(b'length - 1 downto 0);
  begin
    for i in nb'range loop
      if bv(i) = '0' then
        nb(i) := '1';
      elsif bv(i) = '1' then
        nb(i) := '0';
      else
        nb(i) := 'X';
      end if;
    end loop;
    return add(a, nb, 1);
  end function diff;

  -- The low a'length bits of a * b (normalised, of equal lengths, read as unsigned).
  function mul (a, b : std_logic_vector) return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    alias bv : std_logic_vector(b'length - 1 downto 0) is b;
    variable acc : std_logic_vector(a'length - 1 downto 0);
    variable c, s : natural;
  begin
    if unknown(a) or unknown(b) then
      return xs(a);
    end if;
    for i in acc'range loop
      acc(i) := '0';
    end loop;
    for j in 0 to b'length - 1 loop
      if bv(j) = '1' then
        c := 0;
        for i in j to a'length - 1 loop
          s := c;
          if acc(i) = '1' then
            s := s + 1;
          end if;
          if av(i - j) = '1' then
            s := s + 1;
          end if;
          if s mod 2 = 1 then
            acc(i) := '1';
          else
            acc(i) := '0';
          end if;
          c := s / 2;
        end loop;
      end if;
    end loop;
    return acc;
  end function mul;

  -- The two's complement negation of a (normalised).
  function neg (a : std_logic_vector) return std_logic_vector is
    variable zero : std_logic_vector(a'length - 1 downto 0);
  begin
    zero := i_in(0, zero);
    return diff(zero, a);
  end function neg;

  -- The magnitude of a normalised two's complement number, in as many bits (the most
  -- negative value stays itself, as in hardware).
  function absv (a : std_logic_vector) return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
  begin
    if a'length > 0 then
      if av(a'length - 1) = '1' then
        return neg(a);
      end if;
    end if;
    return a;
  end function absv;

  -- Compares two normalised two's complement numbers of equal lengths: -1, 0 or 1 for
  -- a < b, a = b, a > b, and 2 when either is unknown.
  function cmp (a, b : std_logic_vector) return integer is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    alias bv : std_logic_vector(b'length - 1 downto 0) is b;
    constant n : natural := a'length;
  begin
    if unknown(a) or unknown(b) then
      return 2;
    end if;
    if n = 0 then
      return 0;
    end if;
    if av(n - 1) /= bv(n - 1) then
      if av(n - 1) = '1' then
        return -1;
      end if;
      return 1;
    end if;
    for i in n - 2 downto 0 loop
      if av(i) /= bv(i) then
        if av(i) = '1' then
          return 1;
        end if;
        return -1;
      end if;
    end loop;
    return 0;
  end function cmp;

  -- The value of a normalised unsigned number, at most `most`; -1 when it is unknown.
  function count_of (a : std_logic_vector; most : natural) return integer is
    variable v : natural := 0;
  begin
    if unknown(a) then
      return -1;
    end if;
    for i in a'range loop
      v := v * 2;
      if a(i) = '1' then
        v := v + 1;
      end if;
      if v > most then
        return most;
      end if;
    end loop;
    return v;
  end function count_of;

  -- The value of a normalised unsigned number (0 when unknown).
  function uint (a : std_logic_vector) return integer is
    variable v : integer := 0;
  begin
    if unknown(a) then
      return 0;
    end if;
    for i in a'range loop
      v := v * 2;
      if a(i) = '1' then
        v := v + 1;
      end if;
    end loop;
    return v;
  end function uint;

  -- The value of a normalised two's complement number (0 when unknown).
  function sint (a : std_logic_vector) return integer is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    variable v : integer := 0;
  begin
    if unknown(a) or a'length = 0 then
      return 0;
    end if;
    if av(a'length - 1) = '0' then
      return uint(a);
    end if;
    -- Negative: -(value of the inverted bits) - 1, which stays within integer's range.
    for i in av'range loop
      v := v * 2;
      if av(i) = '0' then
        v := v + 1;
      end if;
    end loop;
    return -v - 1;
  end function sint;

  -- a (normalised) extended with fill or cut to size elements, as each result type: built by
  -- recursion, element size-1 first, since size is not known at elaboration.
  function vbuild (a : std_logic_vector; fill : std_logic; size : natural)
    return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    constant none : std_logic_vector(-1 downto 0) := (others => '0');
    variable e : std_logic := fill;
  begin
    if size = 0 then
      return none;
    end if;
    if size <= a'length then
      e := av(size - 1);
    end if;
    return e & vbuild(a, fill, size - 1);
  end function vbuild;


  -- The fill of a normalised operand extended as unsigned ('0') or signed (its top bit);
  -- 'X' when it is unknown.
  function fill_of (a : std_logic_vector; signed_fill : boolean) return std_logic is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
  begin
    if unknown(a) then
      return 'X';
    elsif signed_fill and a'length > 0 then
      return av(a'length - 1);
    end if;
    return '0';
  end function fill_of;

end package body vams_vector_arith;
