-- ieee.numeric_std (IEEE Std 1076.3), written for vams from the standard's documented
-- interface, on the VHDL-2002 base: the types `unsigned` and `signed` (arrays of std_logic,
-- binary and two's complement numbers, the leftmost element the most significant), their
-- arithmetic, comparisons, shifts, resizing, conversions, logical operators and std_match.
-- Declaration and body (plain VHDL, executed like user code).
--
-- Result lengths as in the standard: "+" and "-" the longer operand's (with a natural or
-- integer, the vector's, the number taken modulo 2**length); "*" the sum of the lengths
-- (with a number, twice the vector's, the number first converted to the vector's length);
-- "/" the left operand's, "rem" and "mod" the right one's (with a number, the vector's).
-- Results are indexed (length-1 downto 0). An operand holding a metavalue ('U', 'X', 'Z',
-- 'W', '-') makes an arithmetic result all 'X', a comparison false ("/=" true) and
-- to_integer 0, without the standard's warnings; a division by zero is reported (severity
-- error) and gives 'X's. Comparisons are numeric, operands of different lengths included.

library ieee;
use ieee.std_logic_1164.all;

package numeric_std is
  type unsigned is array (natural range <>) of std_logic;
  type signed is array (natural range <>) of std_logic;

  function "abs" (arg : signed) return signed;
  function "-" (arg : signed) return signed;
  function "+" (l : unsigned; r : unsigned) return unsigned;
  function "+" (l : signed; r : signed) return signed;
  function "+" (l : unsigned; r : natural) return unsigned;
  function "+" (l : natural; r : unsigned) return unsigned;
  function "+" (l : signed; r : integer) return signed;
  function "+" (l : integer; r : signed) return signed;
  function "-" (l : unsigned; r : unsigned) return unsigned;
  function "-" (l : signed; r : signed) return signed;
  function "-" (l : unsigned; r : natural) return unsigned;
  function "-" (l : natural; r : unsigned) return unsigned;
  function "-" (l : signed; r : integer) return signed;
  function "-" (l : integer; r : signed) return signed;
  function "*" (l : unsigned; r : unsigned) return unsigned;
  function "*" (l : signed; r : signed) return signed;
  function "*" (l : unsigned; r : natural) return unsigned;
  function "*" (l : natural; r : unsigned) return unsigned;
  function "*" (l : signed; r : integer) return signed;
  function "*" (l : integer; r : signed) return signed;
  function "/" (l : unsigned; r : unsigned) return unsigned;
  function "/" (l : signed; r : signed) return signed;
  function "/" (l : unsigned; r : natural) return unsigned;
  function "/" (l : natural; r : unsigned) return unsigned;
  function "/" (l : signed; r : integer) return signed;
  function "/" (l : integer; r : signed) return signed;
  function "rem" (l : unsigned; r : unsigned) return unsigned;
  function "rem" (l : signed; r : signed) return signed;
  function "rem" (l : unsigned; r : natural) return unsigned;
  function "rem" (l : natural; r : unsigned) return unsigned;
  function "rem" (l : signed; r : integer) return signed;
  function "rem" (l : integer; r : signed) return signed;
  function "mod" (l : unsigned; r : unsigned) return unsigned;
  function "mod" (l : signed; r : signed) return signed;
  function "mod" (l : unsigned; r : natural) return unsigned;
  function "mod" (l : natural; r : unsigned) return unsigned;
  function "mod" (l : signed; r : integer) return signed;
  function "mod" (l : integer; r : signed) return signed;
  function ">" (l : unsigned; r : unsigned) return boolean;
  function ">" (l : signed; r : signed) return boolean;
  function ">" (l : natural; r : unsigned) return boolean;
  function ">" (l : integer; r : signed) return boolean;
  function ">" (l : unsigned; r : natural) return boolean;
  function ">" (l : signed; r : integer) return boolean;
  function "<" (l : unsigned; r : unsigned) return boolean;
  function "<" (l : signed; r : signed) return boolean;
  function "<" (l : natural; r : unsigned) return boolean;
  function "<" (l : integer; r : signed) return boolean;
  function "<" (l : unsigned; r : natural) return boolean;
  function "<" (l : signed; r : integer) return boolean;
  function "<=" (l : unsigned; r : unsigned) return boolean;
  function "<=" (l : signed; r : signed) return boolean;
  function "<=" (l : natural; r : unsigned) return boolean;
  function "<=" (l : integer; r : signed) return boolean;
  function "<=" (l : unsigned; r : natural) return boolean;
  function "<=" (l : signed; r : integer) return boolean;
  function ">=" (l : unsigned; r : unsigned) return boolean;
  function ">=" (l : signed; r : signed) return boolean;
  function ">=" (l : natural; r : unsigned) return boolean;
  function ">=" (l : integer; r : signed) return boolean;
  function ">=" (l : unsigned; r : natural) return boolean;
  function ">=" (l : signed; r : integer) return boolean;
  function "=" (l : unsigned; r : unsigned) return boolean;
  function "=" (l : signed; r : signed) return boolean;
  function "=" (l : natural; r : unsigned) return boolean;
  function "=" (l : integer; r : signed) return boolean;
  function "=" (l : unsigned; r : natural) return boolean;
  function "=" (l : signed; r : integer) return boolean;
  function "/=" (l : unsigned; r : unsigned) return boolean;
  function "/=" (l : signed; r : signed) return boolean;
  function "/=" (l : natural; r : unsigned) return boolean;
  function "/=" (l : integer; r : signed) return boolean;
  function "/=" (l : unsigned; r : natural) return boolean;
  function "/=" (l : signed; r : integer) return boolean;
  function shift_left (arg : unsigned; count : natural) return unsigned;
  function shift_right (arg : unsigned; count : natural) return unsigned;
  function shift_left (arg : signed; count : natural) return signed;
  function shift_right (arg : signed; count : natural) return signed;
  function rotate_left (arg : unsigned; count : natural) return unsigned;
  function rotate_right (arg : unsigned; count : natural) return unsigned;
  function rotate_left (arg : signed; count : natural) return signed;
  function rotate_right (arg : signed; count : natural) return signed;
  function "sll" (arg : unsigned; count : integer) return unsigned;
  function "srl" (arg : unsigned; count : integer) return unsigned;
  function "rol" (arg : unsigned; count : integer) return unsigned;
  function "ror" (arg : unsigned; count : integer) return unsigned;
  function "sll" (arg : signed; count : integer) return signed;
  function "srl" (arg : signed; count : integer) return signed;
  function "rol" (arg : signed; count : integer) return signed;
  function "ror" (arg : signed; count : integer) return signed;
  function resize (arg : signed; new_size : natural) return signed;
  function resize (arg : unsigned; new_size : natural) return unsigned;
  function to_integer (arg : unsigned) return natural;
  function to_integer (arg : signed) return integer;
  function to_unsigned (arg : natural; size : natural) return unsigned;
  function to_signed (arg : integer; size : natural) return signed;
  function "not" (l : unsigned) return unsigned;
  function "and" (l, r : unsigned) return unsigned;
  function "or" (l, r : unsigned) return unsigned;
  function "nand" (l, r : unsigned) return unsigned;
  function "nor" (l, r : unsigned) return unsigned;
  function "xor" (l, r : unsigned) return unsigned;
  function "xnor" (l, r : unsigned) return unsigned;
  function "not" (l : signed) return signed;
  function "and" (l, r : signed) return signed;
  function "or" (l, r : signed) return signed;
  function "nand" (l, r : signed) return signed;
  function "nor" (l, r : signed) return signed;
  function "xor" (l, r : signed) return signed;
  function "xnor" (l, r : signed) return signed;
  function std_match (l, r : std_ulogic) return boolean;
  function std_match (l, r : unsigned) return boolean;
  function std_match (l, r : signed) return boolean;
  function std_match (l, r : std_logic_vector) return boolean;
  function std_match (l, r : std_ulogic_vector) return boolean;
  function to_01 (s : unsigned; xmap : std_logic := '0') return unsigned;
  function to_01 (s : signed; xmap : std_logic := '0') return signed;
end package numeric_std;

-- The body, in the plain VHDL that the vams interpreter runs (the same helpers as
-- std_logic_arith's body): operands are first copied into local std_logic_vector variables
-- indexed (n-1 downto 0), bit 0 the least significant, with 'L'/'H' read as '0'/'1' and a
-- vector holding any metavalue replaced by all 'X'. Written within what vams elaborates:
-- array types are converted through an alias that renumbers them (n-1 downto 0) (u2v, v2u,
-- ...), an array passed to a function is always a named object (vams takes a call's bounds
-- from its actuals at elaboration, and a function's result has none), a helper's result
-- length comes from an array argument (`like`) rather than a size number, and a result
-- whose length is a size parameter (resize, to_unsigned, to_signed) is built by recursion
-- with "&" (vams_vector_arith's vbuild, converted).

library ieee;
use ieee.std_logic_1164.all;
use ieee.vams_vector_arith.all;

package body numeric_std is

  function sbuild (a : std_logic_vector; fill : std_logic; size : natural) return signed is
  begin
    return signed(vbuild(a, fill, size));
  end function sbuild;





  -- Element-by-element copies between the three array types, indexed (length-1 downto 0).
  function u2v (a : unsigned) return std_logic_vector is
    alias av : unsigned(a'length - 1 downto 0) is a;
  begin
    return std_logic_vector(av);
  end function u2v;

  function s2v (a : signed) return std_logic_vector is
    alias av : signed(a'length - 1 downto 0) is a;
  begin
    return std_logic_vector(av);
  end function s2v;

  function v2u (a : std_logic_vector) return unsigned is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
  begin
    return unsigned(av);
  end function v2u;

  function v2s (a : std_logic_vector) return signed is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
  begin
    return signed(av);
  end function v2s;

  -- The operands as numbers of like'length bits: an unsigned one zero-extended, a signed one
  -- sign-extended, an integer modulo 2**like'length, a std_ulogic as 0 or 1.
  function u_in (x : unsigned; like : std_logic_vector) return std_logic_vector is
    variable a : std_logic_vector(x'length - 1 downto 0);
  begin
    a := u2v(x);
    a := clean(a);
    return extend(a, false, like);
  end function u_in;

  function s_in (x : signed; like : std_logic_vector) return std_logic_vector is
    variable a : std_logic_vector(x'length - 1 downto 0);
  begin
    a := s2v(x);
    a := clean(a);
    return extend(a, true, like);
  end function s_in;














  function ubuild (a : std_logic_vector; fill : std_logic; size : natural) return unsigned is
  begin
    return unsigned(vbuild(a, fill, size));
  end function ubuild;



  -- Unsigned long division of a by b (normalised, of equal lengths n): the quotient
  -- (want_quotient) or the remainder, in n bits. The partial remainder is kept in n + 2
  -- bits so that cmp, which reads two's complement, sees it as non-negative.
  function udivide (a, b : std_logic_vector; want_quotient : boolean) return std_logic_vector is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
    variable q : std_logic_vector(a'length - 1 downto 0);
    variable rem_v : std_logic_vector(a'length + 1 downto 0);
    variable bw : std_logic_vector(a'length + 1 downto 0);
  begin
    bw := extend(b, false, bw);
    rem_v := i_in(0, rem_v);
    for i in a'length - 1 downto 0 loop
      for k in a'length + 1 downto 1 loop
        rem_v(k) := rem_v(k - 1);
      end loop;
      rem_v(0) := av(i);
      if cmp(rem_v, bw) >= 0 then
        rem_v := diff(rem_v, bw);
        q(i) := '1';
      else
        q(i) := '0';
      end if;
    end loop;
    if want_quotient then
      return q;
    end if;
    return extend(rem_v, false, q);
  end function udivide;

  -- True when the normalised number a is zero.
  function is_zero (a : std_logic_vector) return boolean is
  begin
    for i in a'range loop
      if a(i) /= '0' then
        return false;
      end if;
    end loop;
    return true;
  end function is_zero;

  -- True when a (normalised) read as two's complement (is_signed) is negative.
  function negative (a : std_logic_vector; is_signed : boolean) return boolean is
    alias av : std_logic_vector(a'length - 1 downto 0) is a;
  begin
    if is_signed and a'length > 0 then
      return av(a'length - 1) = '1';
    end if;
    return false;
  end function negative;

  -- a / b truncated toward zero, a rem b (the sign of a) and a mod b (the sign of b), for
  -- normalised operands of equal lengths; all 'X' for an unknown operand, and for a
  -- division by zero after reporting it.
  function quotient (a, b : std_logic_vector; is_signed : boolean) return std_logic_vector is
    variable ma, mb, q : std_logic_vector(a'length - 1 downto 0);
  begin
    if unknown(a) or unknown(b) then
      return xs(a);
    end if;
    assert not is_zero(b) report "NUMERIC_STD.""/"": division by zero" severity error;
    if is_zero(b) then
      return xs(a);
    end if;
    ma := a;
    mb := b;
    if negative(a, is_signed) then
      ma := neg(a);
    end if;
    if negative(b, is_signed) then
      mb := neg(b);
    end if;
    q := udivide(ma, mb, true);
    if negative(a, is_signed) /= negative(b, is_signed) then
      q := neg(q);
    end if;
    return q;
  end function quotient;

  function remainder (a, b : std_logic_vector; is_signed : boolean) return std_logic_vector is
    variable ma, mb, r : std_logic_vector(a'length - 1 downto 0);
  begin
    if unknown(a) or unknown(b) then
      return xs(a);
    end if;
    assert not is_zero(b) report "NUMERIC_STD.""rem""/""mod"": division by zero" severity error;
    if is_zero(b) then
      return xs(a);
    end if;
    ma := a;
    mb := b;
    if negative(a, is_signed) then
      ma := neg(a);
    end if;
    if negative(b, is_signed) then
      mb := neg(b);
    end if;
    r := udivide(ma, mb, false);
    if negative(a, is_signed) then
      r := neg(r);
    end if;
    return r;
  end function remainder;

  function modulo (a, b : std_logic_vector; is_signed : boolean) return std_logic_vector is
    variable r : std_logic_vector(a'length - 1 downto 0);
  begin
    r := remainder(a, b, is_signed);
    if unknown(r) or is_zero(r) then
      return r;
    end if;
    if negative(a, is_signed) /= negative(b, is_signed) then
      r := sum(r, b);
    end if;
    return r;
  end function modulo;

  ---------------------------------------------------------------------------
  -- Arithmetic and comparisons.
  ---------------------------------------------------------------------------

  function "abs" (arg : signed) return signed is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    a := absv(a);
    return v2s(a);
  end function "abs";

  function "-" (arg : signed) return signed is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    a := neg(a);
    return v2s(a);
  end function "-";

  function "+" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : unsigned; r : natural) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : natural; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : signed; r : integer) return signed is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : integer; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "-" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : unsigned; r : natural) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : natural; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : signed; r : integer) return signed is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : integer; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "*" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := l'length + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : signed; r : signed) return signed is
    constant n : natural := l'length + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : unsigned; r : natural) return unsigned is
    constant n : natural := 2 * l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable c : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    c := i_in(r, c);
    b := extend(c, false, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : natural; r : unsigned) return unsigned is
    constant n : natural := 2 * r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable c : std_logic_vector(r'length - 1 downto 0);
  begin
    a := u_in(r, a);
    c := i_in(l, c);
    b := extend(c, false, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : signed; r : integer) return signed is
    constant n : natural := 2 * l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable c : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    c := i_in(r, c);
    b := extend(c, true, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : integer; r : signed) return signed is
    constant n : natural := 2 * r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable c : std_logic_vector(r'length - 1 downto 0);
  begin
    a := s_in(r, a);
    c := i_in(l, c);
    b := extend(c, true, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "/" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "/" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "/" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "rem" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "rem" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "rem" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "mod" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function "mod" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function "mod" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
    variable result : std_logic_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function ">" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function "<" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function ">=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function "=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "/=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function shift_left (arg : unsigned; count : natural) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      if i >= count then
        result(i) := av(i - count);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shift_left;

  function shift_right (arg : unsigned; count : natural) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      if i + count < n then
        result(i) := av(i + count);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shift_right;

  function shift_left (arg : signed; count : natural) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      if i >= count then
        result(i) := av(i - count);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shift_left;

  function shift_right (arg : signed; count : natural) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      if i + count < n then
        result(i) := av(i + count);
      else
        result(i) := av(n - 1);
      end if;
    end loop;
    return result;
  end function shift_right;

  function rotate_left (arg : unsigned; count : natural) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      result(i) := av((i - count) mod n);
    end loop;
    return result;
  end function rotate_left;

  function rotate_right (arg : unsigned; count : natural) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      result(i) := av((i + count) mod n);
    end loop;
    return result;
  end function rotate_right;

  function rotate_left (arg : signed; count : natural) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      result(i) := av((i - count) mod n);
    end loop;
    return result;
  end function rotate_left;

  function rotate_right (arg : signed; count : natural) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    constant n : natural := arg'length;
  begin
    for i in result'range loop
      result(i) := av((i + count) mod n);
    end loop;
    return result;
  end function rotate_right;

  function "sll" (arg : unsigned; count : integer) return unsigned is
  begin
    if count >= 0 then
      return shift_left(arg, count);
    end if;
    return shift_right(arg, -count);
  end function "sll";

  function "srl" (arg : unsigned; count : integer) return unsigned is
  begin
    if count >= 0 then
      return shift_right(arg, count);
    end if;
    return shift_left(arg, -count);
  end function "srl";

  function "rol" (arg : unsigned; count : integer) return unsigned is
  begin
    if count >= 0 then
      return rotate_left(arg, count);
    end if;
    return rotate_right(arg, -count);
  end function "rol";

  function "ror" (arg : unsigned; count : integer) return unsigned is
  begin
    if count >= 0 then
      return rotate_right(arg, count);
    end if;
    return rotate_left(arg, -count);
  end function "ror";

  function "sll" (arg : signed; count : integer) return signed is
  begin
    if count >= 0 then
      return shift_left(arg, count);
    end if;
    return shift_right(arg, -count);
  end function "sll";

  function "srl" (arg : signed; count : integer) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
  begin
    if count < 0 then
      return shift_left(arg, -count);
    end if;
    for i in result'range loop
      if i + count < arg'length then
        result(i) := av(i + count);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function "srl";

  function "rol" (arg : signed; count : integer) return signed is
  begin
    if count >= 0 then
      return rotate_left(arg, count);
    end if;
    return rotate_right(arg, -count);
  end function "rol";

  function "ror" (arg : signed; count : integer) return signed is
  begin
    if count >= 0 then
      return rotate_right(arg, count);
    end if;
    return rotate_left(arg, -count);
  end function "ror";

  ---------------------------------------------------------------------------
  -- Resizing and conversions. resize copies the elements as they are: an unsigned is
  -- zero-extended or keeps its low bits, a signed is sign-extended or keeps its sign bit
  -- and its low size-1 bits. to_integer of an operand holding a metavalue is 0.
  -- Results whose length is size are built element by element (see vbuild).
  ---------------------------------------------------------------------------

  function resize (arg : signed; new_size : natural) return signed is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s2v(arg);
    if new_size = 0 or arg'length = 0 then
      return sbuild(a, '0', new_size);
    end if;
    return a(arg'length - 1) & sbuild(a, a(arg'length - 1), new_size - 1);
  end function resize;

  function resize (arg : unsigned; new_size : natural) return unsigned is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u2v(arg);
    return ubuild(a, '0', new_size);
  end function resize;

  function to_integer (arg : unsigned) return natural is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return uint(a);
  end function to_integer;

  function to_integer (arg : signed) return integer is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return sint(a);
  end function to_integer;

  function to_unsigned (arg : natural; size : natural) return unsigned is
    variable a : std_logic_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return ubuild(a, '0', size);
  end function to_unsigned;

  function to_signed (arg : integer; size : natural) return signed is
    variable a : std_logic_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return sbuild(a, a(31), size);
  end function to_signed;

  ---------------------------------------------------------------------------
  -- Logical operators, element by element (std_logic_1164's); the operands of a binary
  -- one must have equal lengths. Results are indexed (length-1 downto 0).
  ---------------------------------------------------------------------------

  function "not" (l : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := not lv(i);
    end loop;
    return result;
  end function "not";

  function "and" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""and"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) and rv(i);
    end loop;
    return result;
  end function "and";

  function "or" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""or"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) or rv(i);
    end loop;
    return result;
  end function "or";

  function "nand" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""nand"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) nand rv(i);
    end loop;
    return result;
  end function "nand";

  function "nor" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""nor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) nor rv(i);
    end loop;
    return result;
  end function "nor";

  function "xor" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""xor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xor rv(i);
    end loop;
    return result;
  end function "xor";

  function "xnor" (l, r : unsigned) return unsigned is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
    variable result : unsigned(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""xnor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xnor rv(i);
    end loop;
    return result;
  end function "xnor";

  function "not" (l : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    variable result : signed(l'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := not lv(i);
    end loop;
    return result;
  end function "not";

  function "and" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""and"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) and rv(i);
    end loop;
    return result;
  end function "and";

  function "or" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""or"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) or rv(i);
    end loop;
    return result;
  end function "or";

  function "nand" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""nand"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) nand rv(i);
    end loop;
    return result;
  end function "nand";

  function "nor" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""nor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) nor rv(i);
    end loop;
    return result;
  end function "nor";

  function "xor" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""xor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xor rv(i);
    end loop;
    return result;
  end function "xor";

  function "xnor" (l, r : signed) return signed is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
    variable result : signed(l'length - 1 downto 0);
  begin
    assert l'length = r'length
      report "NUMERIC_STD.""xnor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xnor rv(i);
    end loop;
    return result;
  end function "xnor";

  ---------------------------------------------------------------------------
  -- std_match: '-' matches anything, '0'/'L' match each other and so do '1'/'H'; 'U',
  -- 'X', 'Z' and 'W' match only '-'. Vectors of different lengths do not match.
  ---------------------------------------------------------------------------

  function std_match (l, r : std_ulogic) return boolean is
  begin
    if l = '-' or r = '-' then
      return true;
    end if;
    if (l = '0' or l = 'L') and (r = '0' or r = 'L') then
      return true;
    end if;
    return (l = '1' or l = 'H') and (r = '1' or r = 'H');
  end function std_match;

  function std_match (l, r : unsigned) return boolean is
    alias lv : unsigned(l'length - 1 downto 0) is l;
    alias rv : unsigned(r'length - 1 downto 0) is r;
  begin
    if l'length /= r'length then
      return false;
    end if;
    for i in lv'range loop
      if not std_match(lv(i), rv(i)) then
        return false;
      end if;
    end loop;
    return true;
  end function std_match;

  function std_match (l, r : signed) return boolean is
    alias lv : signed(l'length - 1 downto 0) is l;
    alias rv : signed(r'length - 1 downto 0) is r;
  begin
    if l'length /= r'length then
      return false;
    end if;
    for i in lv'range loop
      if not std_match(lv(i), rv(i)) then
        return false;
      end if;
    end loop;
    return true;
  end function std_match;

  function std_match (l, r : std_logic_vector) return boolean is
    alias lv : std_logic_vector(l'length - 1 downto 0) is l;
    alias rv : std_logic_vector(r'length - 1 downto 0) is r;
  begin
    if l'length /= r'length then
      return false;
    end if;
    for i in lv'range loop
      if not std_match(lv(i), rv(i)) then
        return false;
      end if;
    end loop;
    return true;
  end function std_match;

  function std_match (l, r : std_ulogic_vector) return boolean is
    alias lv : std_ulogic_vector(l'length - 1 downto 0) is l;
    alias rv : std_ulogic_vector(r'length - 1 downto 0) is r;
  begin
    if l'length /= r'length then
      return false;
    end if;
    for i in lv'range loop
      if not std_match(lv(i), rv(i)) then
        return false;
      end if;
    end loop;
    return true;
  end function std_match;

  function to_01 (s : unsigned; xmap : std_logic := '0') return unsigned is
    alias sv : unsigned(s'length - 1 downto 0) is s;
    variable result : unsigned(s'length - 1 downto 0);
  begin
    for i in result'range loop
      if sv(i) = '0' or sv(i) = 'L' then
        result(i) := '0';
      elsif sv(i) = '1' or sv(i) = 'H' then
        result(i) := '1';
      else
        for k in result'range loop
          result(k) := xmap;
        end loop;
        return result;
      end if;
    end loop;
    return result;
  end function to_01;

  function to_01 (s : signed; xmap : std_logic := '0') return signed is
    alias sv : signed(s'length - 1 downto 0) is s;
    variable result : signed(s'length - 1 downto 0);
  begin
    for i in result'range loop
      if sv(i) = '0' or sv(i) = 'L' then
        result(i) := '0';
      elsif sv(i) = '1' or sv(i) = 'H' then
        result(i) := '1';
      else
        for k in result'range loop
          result(k) := xmap;
        end loop;
        return result;
      end if;
    end loop;
    return result;
  end function to_01;

end package body numeric_std;
