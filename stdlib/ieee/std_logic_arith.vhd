-- ieee.std_logic_arith: the de-facto arithmetic package of much published VHDL and
-- VHDL-AMS (mixed-signal models of converters use it), written for vams from its documented
-- interface: the types `unsigned` and `signed` (arrays of std_logic), their arithmetic,
-- comparisons, shifts and conversions. Declaration and body (plain VHDL, executed like user
-- code). Semantics as documented for the Synopsys package: two's complement, results
-- indexed (length-1 downto 0), an operand holding a metavalue ('U', 'X', 'Z', 'W', '-')
-- makes an arithmetic result all 'X' (without the original's warning), a comparison with
-- one is false ("/=" true) and conv_integer of one is 0.

library ieee;
use ieee.std_logic_1164.all;

package std_logic_arith is
  type unsigned is array (natural range <>) of std_logic;
  type signed is array (natural range <>) of std_logic;
  subtype small_int is integer range 0 to 1;

  function "+" (l : unsigned; r : unsigned) return unsigned;
  function "+" (l : unsigned; r : unsigned) return std_logic_vector;
  function "+" (l : signed; r : signed) return signed;
  function "+" (l : signed; r : signed) return std_logic_vector;
  function "+" (l : unsigned; r : signed) return signed;
  function "+" (l : unsigned; r : signed) return std_logic_vector;
  function "+" (l : signed; r : unsigned) return signed;
  function "+" (l : signed; r : unsigned) return std_logic_vector;
  function "+" (l : unsigned; r : integer) return unsigned;
  function "+" (l : unsigned; r : integer) return std_logic_vector;
  function "+" (l : integer; r : unsigned) return unsigned;
  function "+" (l : integer; r : unsigned) return std_logic_vector;
  function "+" (l : signed; r : integer) return signed;
  function "+" (l : signed; r : integer) return std_logic_vector;
  function "+" (l : integer; r : signed) return signed;
  function "+" (l : integer; r : signed) return std_logic_vector;
  function "+" (l : unsigned; r : std_ulogic) return unsigned;
  function "+" (l : unsigned; r : std_ulogic) return std_logic_vector;
  function "+" (l : std_ulogic; r : unsigned) return unsigned;
  function "+" (l : std_ulogic; r : unsigned) return std_logic_vector;
  function "+" (l : signed; r : std_ulogic) return signed;
  function "+" (l : signed; r : std_ulogic) return std_logic_vector;
  function "+" (l : std_ulogic; r : signed) return signed;
  function "+" (l : std_ulogic; r : signed) return std_logic_vector;
  function "-" (l : unsigned; r : unsigned) return unsigned;
  function "-" (l : unsigned; r : unsigned) return std_logic_vector;
  function "-" (l : signed; r : signed) return signed;
  function "-" (l : signed; r : signed) return std_logic_vector;
  function "-" (l : unsigned; r : signed) return signed;
  function "-" (l : unsigned; r : signed) return std_logic_vector;
  function "-" (l : signed; r : unsigned) return signed;
  function "-" (l : signed; r : unsigned) return std_logic_vector;
  function "-" (l : unsigned; r : integer) return unsigned;
  function "-" (l : unsigned; r : integer) return std_logic_vector;
  function "-" (l : integer; r : unsigned) return unsigned;
  function "-" (l : integer; r : unsigned) return std_logic_vector;
  function "-" (l : signed; r : integer) return signed;
  function "-" (l : signed; r : integer) return std_logic_vector;
  function "-" (l : integer; r : signed) return signed;
  function "-" (l : integer; r : signed) return std_logic_vector;
  function "-" (l : unsigned; r : std_ulogic) return unsigned;
  function "-" (l : unsigned; r : std_ulogic) return std_logic_vector;
  function "-" (l : std_ulogic; r : unsigned) return unsigned;
  function "-" (l : std_ulogic; r : unsigned) return std_logic_vector;
  function "-" (l : signed; r : std_ulogic) return signed;
  function "-" (l : signed; r : std_ulogic) return std_logic_vector;
  function "-" (l : std_ulogic; r : signed) return signed;
  function "-" (l : std_ulogic; r : signed) return std_logic_vector;
  function "+" (l : unsigned) return unsigned;
  function "+" (l : signed) return signed;
  function "-" (l : signed) return signed;
  function "abs" (l : signed) return signed;
  function "+" (l : signed) return std_logic_vector;
  function "-" (l : signed) return std_logic_vector;
  function "abs" (l : signed) return std_logic_vector;
  function "+" (l : unsigned) return std_logic_vector;
  function "*" (l : unsigned; r : unsigned) return unsigned;
  function "*" (l : unsigned; r : unsigned) return std_logic_vector;
  function "*" (l : signed; r : signed) return signed;
  function "*" (l : signed; r : signed) return std_logic_vector;
  function "*" (l : unsigned; r : signed) return signed;
  function "*" (l : unsigned; r : signed) return std_logic_vector;
  function "*" (l : signed; r : unsigned) return signed;
  function "*" (l : signed; r : unsigned) return std_logic_vector;
  function "<" (l : unsigned; r : unsigned) return boolean;
  function "<" (l : signed; r : signed) return boolean;
  function "<" (l : unsigned; r : signed) return boolean;
  function "<" (l : signed; r : unsigned) return boolean;
  function "<" (l : unsigned; r : integer) return boolean;
  function "<" (l : integer; r : unsigned) return boolean;
  function "<" (l : signed; r : integer) return boolean;
  function "<" (l : integer; r : signed) return boolean;
  function "<=" (l : unsigned; r : unsigned) return boolean;
  function "<=" (l : signed; r : signed) return boolean;
  function "<=" (l : unsigned; r : signed) return boolean;
  function "<=" (l : signed; r : unsigned) return boolean;
  function "<=" (l : unsigned; r : integer) return boolean;
  function "<=" (l : integer; r : unsigned) return boolean;
  function "<=" (l : signed; r : integer) return boolean;
  function "<=" (l : integer; r : signed) return boolean;
  function ">" (l : unsigned; r : unsigned) return boolean;
  function ">" (l : signed; r : signed) return boolean;
  function ">" (l : unsigned; r : signed) return boolean;
  function ">" (l : signed; r : unsigned) return boolean;
  function ">" (l : unsigned; r : integer) return boolean;
  function ">" (l : integer; r : unsigned) return boolean;
  function ">" (l : signed; r : integer) return boolean;
  function ">" (l : integer; r : signed) return boolean;
  function ">=" (l : unsigned; r : unsigned) return boolean;
  function ">=" (l : signed; r : signed) return boolean;
  function ">=" (l : unsigned; r : signed) return boolean;
  function ">=" (l : signed; r : unsigned) return boolean;
  function ">=" (l : unsigned; r : integer) return boolean;
  function ">=" (l : integer; r : unsigned) return boolean;
  function ">=" (l : signed; r : integer) return boolean;
  function ">=" (l : integer; r : signed) return boolean;
  function "=" (l : unsigned; r : unsigned) return boolean;
  function "=" (l : signed; r : signed) return boolean;
  function "=" (l : unsigned; r : signed) return boolean;
  function "=" (l : signed; r : unsigned) return boolean;
  function "=" (l : unsigned; r : integer) return boolean;
  function "=" (l : integer; r : unsigned) return boolean;
  function "=" (l : signed; r : integer) return boolean;
  function "=" (l : integer; r : signed) return boolean;
  function "/=" (l : unsigned; r : unsigned) return boolean;
  function "/=" (l : signed; r : signed) return boolean;
  function "/=" (l : unsigned; r : signed) return boolean;
  function "/=" (l : signed; r : unsigned) return boolean;
  function "/=" (l : unsigned; r : integer) return boolean;
  function "/=" (l : integer; r : unsigned) return boolean;
  function "/=" (l : signed; r : integer) return boolean;
  function "/=" (l : integer; r : signed) return boolean;
  function shl (arg : unsigned; count : unsigned) return unsigned;
  function shl (arg : signed; count : unsigned) return signed;
  function shr (arg : unsigned; count : unsigned) return unsigned;
  function shr (arg : signed; count : unsigned) return signed;
  function conv_integer (arg : integer) return integer;
  function conv_integer (arg : unsigned) return integer;
  function conv_integer (arg : signed) return integer;
  function conv_integer (arg : std_ulogic) return integer;
  function conv_unsigned (arg : integer; size : integer) return unsigned;
  function conv_unsigned (arg : unsigned; size : integer) return unsigned;
  function conv_unsigned (arg : signed; size : integer) return unsigned;
  function conv_unsigned (arg : std_ulogic; size : integer) return unsigned;
  function conv_signed (arg : integer; size : integer) return signed;
  function conv_signed (arg : unsigned; size : integer) return signed;
  function conv_signed (arg : signed; size : integer) return signed;
  function conv_signed (arg : std_ulogic; size : integer) return signed;
  function conv_std_logic_vector (arg : integer; size : integer) return std_logic_vector;
  function conv_std_logic_vector (arg : unsigned; size : integer) return std_logic_vector;
  function conv_std_logic_vector (arg : signed; size : integer) return std_logic_vector;
  function conv_std_logic_vector (arg : std_ulogic; size : integer) return std_logic_vector;
  function ext (arg : std_logic_vector; size : integer) return std_logic_vector;
  function sxt (arg : std_logic_vector; size : integer) return std_logic_vector;
end package std_logic_arith;

-- The body, in the plain VHDL that the vams interpreter runs: operands are first copied into
-- local std_logic_vector variables indexed (n-1 downto 0), bit 0 the least significant, with
-- 'L'/'H' read as '0'/'1' and a vector holding any metavalue ('U', 'X', 'Z', 'W', '-')
-- replaced by all 'X'; the private helpers below then work on those. Written within what
-- vams elaborates: array types are converted through an alias that renumbers them (n-1
-- downto 0) (u2v, v2u, ...), an array passed to a function is always a named object (vams
-- takes a call's bounds from its actuals at elaboration, and a function's result has none), a
-- helper's result length comes from an array argument (`like`) rather than a size number,
-- and a result whose length is a size parameter (conv_unsigned(x, size), ext, sxt) is built
-- by recursion with "&" (vams_vector_arith's vbuild, converted).

library ieee;
use ieee.std_logic_1164.all;
use ieee.vams_vector_arith.all;

package body std_logic_arith is

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



  ---------------------------------------------------------------------------
  -- Arithmetic: "+" and "-" give the longer operand's length (an unsigned operand beside
  -- a signed one counts one bit more, its sign); with an integer or a std_ulogic, the
  -- vector's length; "*" the sum of the lengths. An integer operand is taken modulo
  -- 2**length, so a negative one works as its two's complement.
  ---------------------------------------------------------------------------

  function "+" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : unsigned; r : unsigned) return std_logic_vector is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return a;
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

  function "+" (l : signed; r : signed) return std_logic_vector is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : unsigned; r : signed) return signed is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : unsigned; r : signed) return std_logic_vector is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : signed; r : unsigned) return signed is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : signed; r : unsigned) return std_logic_vector is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : unsigned; r : integer) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : unsigned; r : integer) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : integer; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : integer; r : unsigned) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return a;
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

  function "+" (l : signed; r : integer) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := sum(a, b);
    return a;
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

  function "+" (l : integer; r : signed) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : unsigned; r : std_ulogic) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := l_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : unsigned; r : std_ulogic) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := l_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : std_ulogic; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return v2u(a);
  end function "+";

  function "+" (l : std_ulogic; r : unsigned) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := u_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : signed; r : std_ulogic) return signed is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := l_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : signed; r : std_ulogic) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := l_in(r, b);
    a := sum(a, b);
    return a;
  end function "+";

  function "+" (l : std_ulogic; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return v2s(a);
  end function "+";

  function "+" (l : std_ulogic; r : signed) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := s_in(r, b);
    a := sum(a, b);
    return a;
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

  function "-" (l : unsigned; r : unsigned) return std_logic_vector is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return a;
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

  function "-" (l : signed; r : signed) return std_logic_vector is
    constant n : natural := (l'length + r'length + abs(l'length - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : unsigned; r : signed) return signed is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : unsigned; r : signed) return std_logic_vector is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : signed; r : unsigned) return signed is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : signed; r : unsigned) return std_logic_vector is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : unsigned; r : integer) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : unsigned; r : integer) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : integer; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : integer; r : unsigned) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return a;
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

  function "-" (l : signed; r : integer) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := i_in(r, b);
    a := diff(a, b);
    return a;
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

  function "-" (l : integer; r : signed) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : unsigned; r : std_ulogic) return unsigned is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := l_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : unsigned; r : std_ulogic) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := l_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : std_ulogic; r : unsigned) return unsigned is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return v2u(a);
  end function "-";

  function "-" (l : std_ulogic; r : unsigned) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := u_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : signed; r : std_ulogic) return signed is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := l_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : signed; r : std_ulogic) return std_logic_vector is
    constant n : natural := l'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := l_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "-" (l : std_ulogic; r : signed) return signed is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return v2s(a);
  end function "-";

  function "-" (l : std_ulogic; r : signed) return std_logic_vector is
    constant n : natural := r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := l_in(l, a);
    b := s_in(r, b);
    a := diff(a, b);
    return a;
  end function "-";

  function "+" (l : unsigned) return unsigned is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    return v2u(a);
  end function "+";

  function "+" (l : signed) return signed is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    return v2s(a);
  end function "+";

  function "-" (l : signed) return signed is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    a := neg(a);
    return v2s(a);
  end function "-";

  function "abs" (l : signed) return signed is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    a := absv(a);
    return v2s(a);
  end function "abs";

  function "+" (l : signed) return std_logic_vector is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    return a;
  end function "+";

  function "-" (l : signed) return std_logic_vector is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    a := neg(a);
    return a;
  end function "-";

  function "abs" (l : signed) return std_logic_vector is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := s_in(l, a);
    a := absv(a);
    return a;
  end function "abs";

  function "+" (l : unsigned) return std_logic_vector is
    variable a : std_logic_vector(l'length - 1 downto 0);
  begin
    a := u_in(l, a);
    return a;
  end function "+";

  function "*" (l : unsigned; r : unsigned) return unsigned is
    constant n : natural := l'length + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return v2u(a);
  end function "*";

  function "*" (l : unsigned; r : unsigned) return std_logic_vector is
    constant n : natural := l'length + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return a;
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

  function "*" (l : signed; r : signed) return std_logic_vector is
    constant n : natural := l'length + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := s_in(r, b);
    a := mul(a, b);
    return a;
  end function "*";

  function "*" (l : unsigned; r : signed) return signed is
    constant n : natural := l'length + 1 + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : unsigned; r : signed) return std_logic_vector is
    constant n : natural := l'length + 1 + r'length;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    a := mul(a, b);
    return a;
  end function "*";

  function "*" (l : signed; r : unsigned) return signed is
    constant n : natural := l'length + r'length + 1;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return v2s(a);
  end function "*";

  function "*" (l : signed; r : unsigned) return std_logic_vector is
    constant n : natural := l'length + r'length + 1;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    a := mul(a, b);
    return a;
  end function "*";

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

  function "<" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = -1;
  end function "<";

  function "<" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function "<" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
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

  function "<=" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

  function "<=" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function "<=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) <= 0;
  end function "<=";

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

  function ">" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

  function ">" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function ">" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 1;
  end function ">";

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

  function ">=" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(b, a) <= 0;
  end function ">=";

  function ">=" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function ">=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
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

  function "=" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) = 0;
  end function "=";

  function "=" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function "=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
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

  function "/=" (l : unsigned; r : signed) return boolean is
    constant n : natural := (l'length + 1 + r'length + abs(l'length + 1 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : signed; r : unsigned) return boolean is
    constant n : natural := (l'length + r'length + 1 + abs(l'length - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := s_in(l, a);
    b := u_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : unsigned; r : integer) return boolean is
    constant n : natural := (l'length + 1 + 32 + abs(l'length + 1 - (32))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := u_in(l, a);
    b := i_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  function "/=" (l : integer; r : unsigned) return boolean is
    constant n : natural := (32 + r'length + 1 + abs(32 - (r'length + 1))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := u_in(r, b);
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

  function "/=" (l : integer; r : signed) return boolean is
    constant n : natural := (32 + r'length + abs(32 - (r'length))) / 2;
    variable a, b : std_logic_vector(n - 1 downto 0);
  begin
    a := i_in(l, a);
    b := s_in(r, b);
    return cmp(a, b) /= 0;
  end function "/=";

  ---------------------------------------------------------------------------
  -- Shifts: the count is unsigned; shl fills with '0', shr with '0' (unsigned) or the sign
  -- bit (signed). The shifted elements are copied as they are; an unknown count gives 'X's.
  ---------------------------------------------------------------------------

  function shl (arg : unsigned; count : unsigned) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    variable cv : std_logic_vector(count'length - 1 downto 0);
    variable c : integer;
  begin
    cv := u_in(count, cv);
    c := count_of(cv, arg'length);
    for i in result'range loop
      if c < 0 then
        result(i) := 'X';
      elsif i >= c then
        result(i) := av(i - c);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shl;

  function shl (arg : signed; count : unsigned) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    variable cv : std_logic_vector(count'length - 1 downto 0);
    variable c : integer;
  begin
    cv := u_in(count, cv);
    c := count_of(cv, arg'length);
    for i in result'range loop
      if c < 0 then
        result(i) := 'X';
      elsif i >= c then
        result(i) := av(i - c);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shl;

  function shr (arg : unsigned; count : unsigned) return unsigned is
    alias av : unsigned(arg'length - 1 downto 0) is arg;
    variable result : unsigned(arg'length - 1 downto 0);
    variable cv : std_logic_vector(count'length - 1 downto 0);
    variable c : integer;
  begin
    cv := u_in(count, cv);
    c := count_of(cv, arg'length);
    for i in result'range loop
      if c < 0 then
        result(i) := 'X';
      elsif i + c < arg'length then
        result(i) := av(i + c);
      else
        result(i) := '0';
      end if;
    end loop;
    return result;
  end function shr;

  function shr (arg : signed; count : unsigned) return signed is
    alias av : signed(arg'length - 1 downto 0) is arg;
    variable result : signed(arg'length - 1 downto 0);
    variable cv : std_logic_vector(count'length - 1 downto 0);
    variable c : integer;
  begin
    cv := u_in(count, cv);
    c := count_of(cv, arg'length);
    for i in result'range loop
      if c < 0 then
        result(i) := 'X';
      elsif i + c < arg'length then
        result(i) := av(i + c);
      else
        result(i) := av(arg'length - 1);
      end if;
    end loop;
    return result;
  end function shr;

  ---------------------------------------------------------------------------
  -- Conversions. conv_integer of an operand holding a metavalue is 0; the vector
  -- conversions give 'X's for it. Vectors are zero-extended (unsigned, std_ulogic) or
  -- sign-extended (signed, integer) to size, or keep their low size bits. Results whose
  -- length is size are built element by element (see vbuild).
  ---------------------------------------------------------------------------

  function conv_integer (arg : integer) return integer is
  begin
    return arg;
  end function conv_integer;

  function conv_integer (arg : unsigned) return integer is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return uint(a);
  end function conv_integer;

  function conv_integer (arg : signed) return integer is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return sint(a);
  end function conv_integer;

  function conv_integer (arg : std_ulogic) return integer is
    variable a : std_logic_vector(0 downto 0);
  begin
    a := l_in(arg, a);
    return uint(a);
  end function conv_integer;

  function conv_unsigned (arg : integer; size : integer) return unsigned is
    variable a : std_logic_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return ubuild(a, a(31), size);
  end function conv_unsigned;

  function conv_unsigned (arg : unsigned; size : integer) return unsigned is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return ubuild(a, fill_of(a, false), size);
  end function conv_unsigned;

  function conv_unsigned (arg : signed; size : integer) return unsigned is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return ubuild(a, fill_of(a, true), size);
  end function conv_unsigned;

  function conv_unsigned (arg : std_ulogic; size : integer) return unsigned is
    variable a : std_logic_vector(0 downto 0);
  begin
    a := l_in(arg, a);
    return ubuild(a, fill_of(a, false), size);
  end function conv_unsigned;

  function conv_signed (arg : integer; size : integer) return signed is
    variable a : std_logic_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return sbuild(a, a(31), size);
  end function conv_signed;

  function conv_signed (arg : unsigned; size : integer) return signed is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return sbuild(a, fill_of(a, false), size);
  end function conv_signed;

  function conv_signed (arg : signed; size : integer) return signed is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return sbuild(a, fill_of(a, true), size);
  end function conv_signed;

  function conv_signed (arg : std_ulogic; size : integer) return signed is
    variable a : std_logic_vector(0 downto 0);
  begin
    a := l_in(arg, a);
    return sbuild(a, fill_of(a, false), size);
  end function conv_signed;

  function conv_std_logic_vector (arg : integer; size : integer) return std_logic_vector is
    variable a : std_logic_vector(31 downto 0);
  begin
    a := i_in(arg, a);
    return vbuild(a, a(31), size);
  end function conv_std_logic_vector;

  function conv_std_logic_vector (arg : unsigned; size : integer) return std_logic_vector is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := u_in(arg, a);
    return vbuild(a, fill_of(a, false), size);
  end function conv_std_logic_vector;

  function conv_std_logic_vector (arg : signed; size : integer) return std_logic_vector is
    variable a : std_logic_vector(arg'length - 1 downto 0);
  begin
    a := s_in(arg, a);
    return vbuild(a, fill_of(a, true), size);
  end function conv_std_logic_vector;

  function conv_std_logic_vector (arg : std_ulogic; size : integer) return std_logic_vector is
    variable a : std_logic_vector(0 downto 0);
  begin
    a := l_in(arg, a);
    return vbuild(a, fill_of(a, false), size);
  end function conv_std_logic_vector;

  -- ext and sxt copy the elements as they are (no metavalue check): zero or sign
  -- extension to size, or the low size elements when size is shorter.
  function ext (arg : std_logic_vector; size : integer) return std_logic_vector is
  begin
    return vbuild(arg, '0', size);
  end function ext;

  function sxt (arg : std_logic_vector; size : integer) return std_logic_vector is
    alias av : std_logic_vector(arg'length - 1 downto 0) is arg;
  begin
    if arg'length = 0 then
      return vbuild(arg, '0', size);
    end if;
    return vbuild(arg, av(arg'length - 1), size);
  end function sxt;

end package body std_logic_arith;
