-- ieee.numeric_bit (IEEE Std 1076.3), written for vams from the standard's documented
-- interface, on the VHDL-2002 base: the types `unsigned` and `signed` (arrays of bit, binary
-- and two's complement numbers, the leftmost element the most significant), their
-- arithmetic, comparisons, shifts, resizing, conversions, logical operators and the clock
-- edge functions on bit. The bit-based twin of ieee.numeric_std, without its metavalue
-- handling (a bit is always '0' or '1') and without std_match and to_01, which 1076.3 does
-- not give numeric_bit. Declaration and body (plain VHDL, executed like user code).
--
-- Result lengths as in the standard: "+" and "-" the longer operand's (with a natural or
-- integer, the vector's, the number taken modulo 2**length); "*" the sum of the lengths
-- (with a number, twice the vector's, the number first converted to the vector's length);
-- "/" the left operand's, "rem" and "mod" the right one's (with a number, the vector's).
-- Results are indexed (length-1 downto 0), except those of resize, to_unsigned and
-- to_signed, built by concatenation and so numbered from 0 up (as numeric_std's here;
-- assigned to a constrained object, only their length matters). A division by zero is
-- reported (severity error) and gives all '0'. Comparisons are numeric, operands of
-- different lengths included. "sll" and "srl" are logical on signed, as the standard has
-- them; shift_right of a signed fills with its sign.

package numeric_bit is
  type unsigned is array (natural range <>) of bit;
  type signed is array (natural range <>) of bit;

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
  function rising_edge (signal s : bit) return boolean;
  function falling_edge (signal s : bit) return boolean;
end package numeric_bit;

-- The body, in the plain VHDL that the vams interpreter runs, within what vams elaborates
-- (as numeric_std's body): operands are first copied into local bit_vector variables indexed
-- (n-1 downto 0), bit 0 the least significant, through an alias that renumbers them (u2v,
-- v2u, ...); an array passed to a function is always a named object; a helper's result
-- length comes from an array argument (`like`) rather than a size number; a result whose
-- length is a size parameter (resize, to_unsigned, to_signed) is built by recursion with "&"
-- (vbuild). The helpers are bit versions of ieee.vams_vector_arith's, kept private here so
-- that numeric_bit needs no other package.

package body numeric_bit is

  -- Element-by-element copies between the three array types, indexed (length-1 downto 0).
  function u2v (a : unsigned) return bit_vector is
    alias av : unsigned(a'length - 1 downto 0) is a;
  begin
    return bit_vector(av);
  end function u2v;

  function s2v (a : signed) return bit_vector is
    alias av : signed(a'length - 1 downto 0) is a;
  begin
    return bit_vector(av);
  end function s2v;

  function v2u (a : bit_vector) return unsigned is
    alias av : bit_vector(a'length - 1 downto 0) is a;
  begin
    return unsigned(av);
  end function v2u;

  function v2s (a : bit_vector) return signed is
    alias av : bit_vector(a'length - 1 downto 0) is a;
  begin
    return signed(av);
  end function v2s;

  -- a zero-extended (fill '0') or sign-extended (fill its top bit) to the length of like, or
  -- its low bits.
  function extend (a : bit_vector; signed_fill : boolean; like : bit_vector)
    return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    variable result : bit_vector(like'length - 1 downto 0);
    variable fill : bit := '0';
  begin
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

  -- The operands as numbers of like'length bits: an unsigned one zero-extended, a signed one
  -- sign-extended, an integer modulo 2**like'length (two's complement).
  function u_in (x : unsigned; like : bit_vector) return bit_vector is
    variable a : bit_vector(x'length - 1 downto 0);
  begin
    a := u2v(x);
    return extend(a, false, like);
  end function u_in;

  function s_in (x : signed; like : bit_vector) return bit_vector is
    variable a : bit_vector(x'length - 1 downto 0);
  begin
    a := s2v(x);
    return extend(a, true, like);
  end function s_in;

  function i_in (x : integer; like : bit_vector) return bit_vector is
    variable result : bit_vector(like'length - 1 downto 0);
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

  -- a + b + carry in a'length bits (a and b of equal lengths).
  function add (a, b : bit_vector; carry : natural) return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    variable result : bit_vector(a'length - 1 downto 0);
    variable c : natural := carry;
    variable s : natural;
  begin
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

  function sum (a, b : bit_vector) return bit_vector is
  begin
    return add(a, b, 0);
  end function sum;

  -- a - b: a + not b + 1.
  function diff (a, b : bit_vector) return bit_vector is
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    variable nb : bit_vector(b'length - 1 downto 0);
  begin
    for i in nb'range loop
      nb(i) := not bv(i);
    end loop;
    return add(a, nb, 1);
  end function diff;

  -- The low a'length bits of a * b (of equal lengths, read as unsigned).
  function mul (a, b : bit_vector) return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    variable acc : bit_vector(a'length - 1 downto 0);
    variable c, s : natural;
  begin
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

  -- The two's complement negation of a.
  function neg (a : bit_vector) return bit_vector is
    variable zero : bit_vector(a'length - 1 downto 0);
  begin
    zero := i_in(0, zero);
    return diff(zero, a);
  end function neg;

  -- The magnitude of a two's complement number, in as many bits (the most negative value
  -- stays itself, as in hardware).
  function absv (a : bit_vector) return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
  begin
    if a'length > 0 then
      if av(a'length - 1) = '1' then
        return neg(a);
      end if;
    end if;
    return a;
  end function absv;

  -- Compares two two's complement numbers of equal lengths: -1, 0 or 1 for a < b, a = b,
  -- a > b. An unsigned operand is given one bit more than it needs, a '0' on top.
  function cmp (a, b : bit_vector) return integer is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    constant n : natural := a'length;
  begin
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

  -- The value of an unsigned number.
  function uint (a : bit_vector) return integer is
    variable v : integer := 0;
  begin
    for i in a'range loop
      v := v * 2;
      if a(i) = '1' then
        v := v + 1;
      end if;
    end loop;
    return v;
  end function uint;

  -- The value of a two's complement number (0 for a null one).
  function sint (a : bit_vector) return integer is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    variable v : integer := 0;
  begin
    if a'length = 0 then
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

  -- a extended with fill or cut to size elements: built by recursion, element size-1
  -- first, since size is not known at elaboration.
  function vbuild (a : bit_vector; fill : bit; size : natural) return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    constant none : bit_vector(-1 downto 0) := (others => '0');
    variable e : bit := fill;
  begin
    if size = 0 then
      return none;
    end if;
    if size <= a'length then
      e := av(size - 1);
    end if;
    return e & vbuild(a, fill, size - 1);
  end function vbuild;

  function ubuild (a : bit_vector; fill : bit; size : natural) return unsigned is
  begin
    return unsigned(vbuild(a, fill, size));
  end function ubuild;

  function sbuild (a : bit_vector; fill : bit; size : natural) return signed is
  begin
    return signed(vbuild(a, fill, size));
  end function sbuild;

  -- Unsigned long division of a by b (of equal lengths n): the quotient (want_quotient) or
  -- the remainder, in n bits. The partial remainder is kept in n + 2 bits so that cmp, which
  -- reads two's complement, sees it as non-negative.
  function udivide (a, b : bit_vector; want_quotient : boolean) return bit_vector is
    alias av : bit_vector(a'length - 1 downto 0) is a;
    variable q : bit_vector(a'length - 1 downto 0);
    variable rem_v : bit_vector(a'length + 1 downto 0);
    variable bw : bit_vector(a'length + 1 downto 0);
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

  -- True when the number a is zero.
  function is_zero (a : bit_vector) return boolean is
  begin
    for i in a'range loop
      if a(i) /= '0' then
        return false;
      end if;
    end loop;
    return true;
  end function is_zero;

  -- True when a read as two's complement (is_signed) is negative.
  function negative (a : bit_vector; is_signed : boolean) return boolean is
    alias av : bit_vector(a'length - 1 downto 0) is a;
  begin
    if is_signed and a'length > 0 then
      return av(a'length - 1) = '1';
    end if;
    return false;
  end function negative;

  -- a / b truncated toward zero, a rem b (the sign of a) and a mod b (the sign of b), for
  -- operands of equal lengths; all '0' for a division by zero, after reporting it.
  function quotient (a, b : bit_vector; is_signed : boolean) return bit_vector is
    variable ma, mb, q : bit_vector(a'length - 1 downto 0);
  begin
    assert not is_zero(b) report "NUMERIC_BIT.""/"": division by zero" severity error;
    if is_zero(b) then
      return i_in(0, q);
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

  function remainder (a, b : bit_vector; is_signed : boolean) return bit_vector is
    variable ma, mb, r : bit_vector(a'length - 1 downto 0);
  begin
    assert not is_zero(b) report "NUMERIC_BIT.""rem""/""mod"": division by zero" severity error;
    if is_zero(b) then
      return i_in(0, r);
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

  function modulo (a, b : bit_vector; is_signed : boolean) return bit_vector is
    variable r : bit_vector(a'length - 1 downto 0);
  begin
    r := remainder(a, b, is_signed);
    if is_zero(r) then
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
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    a := absv(a);
    return v2s(a);
  end function "abs";

  function "-" (arg : signed) return signed is
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    a := neg(a);
    return v2s(a);
  end function "-";

  function "+" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : unsigned; r : natural) return unsigned is
    constant n : natural := l'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : natural; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : signed; r : integer) return signed is
    constant n : natural := l'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : integer; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "-" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : unsigned; r : natural) return unsigned is
    constant n : natural := l'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : natural; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : signed; r : integer) return signed is
    constant n : natural := l'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : integer; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "*" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := l'length + r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : signed; r : signed) return signed is
    constant n : natural := l'length + r'length;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : unsigned; r : natural) return unsigned is
    constant n : natural := 2 * l'length;
    variable a, b : bit_vector(n - 1 downto 0);
    variable c : bit_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    c := i_in(r, c);
    b := extend(c, false, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : natural; r : unsigned) return unsigned is
    constant n : natural := 2 * r'length;
    variable a, b : bit_vector(n - 1 downto 0);
    variable c : bit_vector(r'length - 1 downto 0);
  begin
    a := u_in(r, a);
    c := i_in(l, c);
    b := extend(c, false, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : signed; r : integer) return signed is
    constant n : natural := 2 * l'length;
    variable a, b : bit_vector(n - 1 downto 0);
    variable c : bit_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    c := i_in(r, c);
    b := extend(c, true, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : integer; r : signed) return signed is
    constant n : natural := 2 * r'length;
    variable a, b : bit_vector(n - 1 downto 0);
    variable c : bit_vector(r'length - 1 downto 0);
  begin
    a := s_in(r, a);
    c := i_in(l, c);
    b := extend(c, true, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "/" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "/" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := quotient(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "/";

  function "/" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "/" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := quotient(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "/";

  function "rem" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "rem" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := remainder(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "rem";

  function "rem" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "rem" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := remainder(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "rem";

  function "mod" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : signed; r : signed) return signed is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function "mod" (l : unsigned; r : natural) return unsigned is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : natural; r : unsigned) return unsigned is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := modulo(a, b, false);
    result := extend(a, false, result);
    return v2u(result);
  end function "mod";

  function "mod" (l : signed; r : integer) return signed is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function "mod" (l : integer; r : signed) return signed is
    constant n : natural := (r'length + 32 + abs(r'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
    variable result : bit_vector(r'length - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := modulo(a, b, true);
    result := extend(a, true, result);
    return v2s(result);
  end function "mod";

  function ">" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function "<" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function ">=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function "=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "/=" (l : unsigned; r : unsigned) return boolean is
    constant n : natural := (l'length + 1 + r'length + 1 + abs(l'length + 1 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : signed; r : signed) return boolean is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : natural; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : unsigned; r : natural) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : signed; r : integer) return boolean is
    constant n : natural := (l'length + 32 + abs(l'length - (32))) / 2;
    variable a, b : bit_vector(n - 1 downto 0);
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

  -- "sll" and "srl" are logical on signed too (no sign fill, whatever the direction).
  function "sll" (arg : signed; count : integer) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
  begin
    if count >= 0 then
      return shift_left(arg, count);
    end if;
    for i in result'range loop
      if i - count < arg'length then
        result(i) := av(i - count);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
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
  -- and its low size-1 bits.
  -- Results whose length is size are built element by element (see vbuild).
  ---------------------------------------------------------------------------

  function resize (arg : signed; new_size : natural) return signed is
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := s2v(arg);
    if new_size = 0 or arg'length = 0 then
      return sbuild(a, '0', new_size);
    end if;
    return a(arg'length - 1) & sbuild(a, a(arg'length - 1), new_size - 1);
  end function resize;

  function resize (arg : unsigned; new_size : natural) return unsigned is
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := u2v(arg);
    return ubuild(a, '0', new_size);
  end function resize;

  function to_integer (arg : unsigned) return natural is
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return uint(a);
  end function to_integer;

  function to_integer (arg : signed) return integer is
    variable a : bit_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return sint(a);
  end function to_integer;

  function to_unsigned (arg : natural; size : natural) return unsigned is
    variable a : bit_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return ubuild(a, '0', size);
  end function to_unsigned;

  function to_signed (arg : integer; size : natural) return signed is
    variable a : bit_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return sbuild(a, a(31), size);
  end function to_signed;

  ---------------------------------------------------------------------------
  -- Logical operators, element by element (bit's); the operands of a binary
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
      report "NUMERIC_BIT.""and"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""or"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""nand"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""nor"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""xor"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""xnor"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""and"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""or"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""nand"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""nor"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""xor"": arguments are not of the same length"
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
      report "NUMERIC_BIT.""xnor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xnor rv(i);
    end loop;
    return result;
  end function "xnor";

  ---------------------------------------------------------------------------
  -- Clock edges: an event on s that made it '1' (rising) or '0' (falling); a bit has no
  -- other values, so its previous value was the other one.
  ---------------------------------------------------------------------------

  function rising_edge (signal s : bit) return boolean is
  begin
    return s'event and s = '1';
  end function rising_edge;

  function falling_edge (signal s : bit) return boolean is
  begin
    return s'event and s = '0';
  end function falling_edge;

end package body numeric_bit;
