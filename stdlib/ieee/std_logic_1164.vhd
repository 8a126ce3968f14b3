-- IEEE.STD_LOGIC_1164 for vams: the nine-valued logic of IEEE Std 1164, declaration and body.
--
-- The body is ordinary VHDL that the vams simulator executes. The scalar operators
-- and conversions state IEEE's tables as rules (if/elsif on the operand values),
-- because vams cannot index arrays by an enumeration type yet; the tables stay as
-- their specification. The vector operators loop over their operands and apply the
-- scalar operators element by element.

package std_logic_1164 is

  -------------------------------------------------------------------
  -- Logic state system (unresolved)
  -------------------------------------------------------------------
  type std_ulogic is ( 'U',   -- Uninitialized
                       'X',   -- Forcing  Unknown
                       '0',   -- Forcing  0
                       '1',   -- Forcing  1
                       'Z',   -- High Impedance
                       'W',   -- Weak     Unknown
                       'L',   -- Weak     0
                       'H',   -- Weak     1
                       '-'    -- Don't care
                     );

  -------------------------------------------------------------------
  -- Unconstrained array of std_ulogic
  -------------------------------------------------------------------
  type std_ulogic_vector is array (natural range <>) of std_ulogic;

  -------------------------------------------------------------------
  -- Resolution function
  -------------------------------------------------------------------
  function resolved (s : std_ulogic_vector) return std_ulogic;

  -------------------------------------------------------------------
  -- Industry standard logic type (resolved) and its vector
  -------------------------------------------------------------------
  subtype std_logic is resolved std_ulogic;

  type std_logic_vector is array (natural range <>) of std_logic;

  -------------------------------------------------------------------
  -- Common subtypes
  -------------------------------------------------------------------
  subtype X01   is resolved std_ulogic range 'X' to '1';  -- ('X', '0', '1')
  subtype X01Z  is resolved std_ulogic range 'X' to 'Z';  -- ('X', '0', '1', 'Z')
  subtype UX01  is resolved std_ulogic range 'U' to '1';  -- ('U', 'X', '0', '1')
  subtype UX01Z is resolved std_ulogic range 'U' to 'Z';  -- ('U', 'X', '0', '1', 'Z')

  -------------------------------------------------------------------
  -- Overloaded logical operators
  -------------------------------------------------------------------
  function "and"   (l : std_ulogic; r : std_ulogic) return UX01;
  function "nand"  (l : std_ulogic; r : std_ulogic) return UX01;
  function "or"    (l : std_ulogic; r : std_ulogic) return UX01;
  function "nor"   (l : std_ulogic; r : std_ulogic) return UX01;
  function "xor"   (l : std_ulogic; r : std_ulogic) return UX01;
  function "xnor"  (l : std_ulogic; r : std_ulogic) return UX01;
  function "not"   (l : std_ulogic) return UX01;

  -------------------------------------------------------------------
  -- Vectorized overloaded logical operators
  -- (binary ones require operands of equal length; the result is indexed 1 to l'length)
  -------------------------------------------------------------------
  function "and"   (l, r : std_logic_vector) return std_logic_vector;
  function "nand"  (l, r : std_logic_vector) return std_logic_vector;
  function "or"    (l, r : std_logic_vector) return std_logic_vector;
  function "nor"   (l, r : std_logic_vector) return std_logic_vector;
  function "xor"   (l, r : std_logic_vector) return std_logic_vector;
  function "xnor"  (l, r : std_logic_vector) return std_logic_vector;
  function "not"   (l : std_logic_vector) return std_logic_vector;

  function "and"   (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "nand"  (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "or"    (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "nor"   (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "xor"   (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "xnor"  (l, r : std_ulogic_vector) return std_ulogic_vector;
  function "not"   (l : std_ulogic_vector) return std_ulogic_vector;

  -------------------------------------------------------------------
  -- Conversion functions
  -- (XMAP is the bit returned for a value that is neither a 0 nor a 1)
  -------------------------------------------------------------------
  function to_bit       (s : std_ulogic;        xmap : bit := '0') return bit;
  function to_bitvector (s : std_logic_vector;  xmap : bit := '0') return bit_vector;
  function to_bitvector (s : std_ulogic_vector; xmap : bit := '0') return bit_vector;

  function to_stdulogic       (b : bit)               return std_ulogic;
  function to_stdlogicvector  (b : bit_vector)        return std_logic_vector;
  function to_stdlogicvector  (s : std_ulogic_vector) return std_logic_vector;
  function to_stdulogicvector (b : bit_vector)        return std_ulogic_vector;
  function to_stdulogicvector (s : std_logic_vector)  return std_ulogic_vector;

  -------------------------------------------------------------------
  -- Strength strippers and type convertors
  -------------------------------------------------------------------
  function to_x01  (s : std_logic_vector)  return std_logic_vector;
  function to_x01  (s : std_ulogic_vector) return std_ulogic_vector;
  function to_x01  (s : std_ulogic)        return X01;
  function to_x01  (b : bit_vector)        return std_logic_vector;
  function to_x01  (b : bit_vector)        return std_ulogic_vector;
  function to_x01  (b : bit)               return X01;

  function to_x01z (s : std_logic_vector)  return std_logic_vector;
  function to_x01z (s : std_ulogic_vector) return std_ulogic_vector;
  function to_x01z (s : std_ulogic)        return X01Z;
  function to_x01z (b : bit_vector)        return std_logic_vector;
  function to_x01z (b : bit_vector)        return std_ulogic_vector;
  function to_x01z (b : bit)               return X01Z;

  function to_ux01 (s : std_logic_vector)  return std_logic_vector;
  function to_ux01 (s : std_ulogic_vector) return std_ulogic_vector;
  function to_ux01 (s : std_ulogic)        return UX01;
  function to_ux01 (b : bit_vector)        return std_logic_vector;
  function to_ux01 (b : bit_vector)        return std_ulogic_vector;
  function to_ux01 (b : bit)               return UX01;

  -------------------------------------------------------------------
  -- Edge detection
  -------------------------------------------------------------------
  function rising_edge  (signal s : std_ulogic) return boolean;
  function falling_edge (signal s : std_ulogic) return boolean;

  -------------------------------------------------------------------
  -- Object contains an unknown
  -------------------------------------------------------------------
  function is_x (s : std_ulogic_vector) return boolean;
  function is_x (s : std_logic_vector)  return boolean;
  function is_x (s : std_ulogic)        return boolean;

end package std_logic_1164;

package body std_logic_1164 is

  -------------------------------------------------------------------
  -- Tables
  -------------------------------------------------------------------
  type stdlogic_1d    is array (std_ulogic) of std_ulogic;
  type stdlogic_table is array (std_ulogic, std_ulogic) of std_ulogic;

  -- Resolution of two drivers: the stronger wins; equal strengths that disagree
  -- give X (forcing) or W (weak). U wins over everything; '-' with anything else gives X.
  constant resolution_table : stdlogic_table := (
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'U', 'U', 'U', 'U', 'U', 'U', 'U', 'U'),  -- U
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X'),  -- X
      ('U', 'X', '0', 'X', '0', '0', '0', '0', 'X'),  -- 0
      ('U', 'X', 'X', '1', '1', '1', '1', '1', 'X'),  -- 1
      ('U', 'X', '0', '1', 'Z', 'W', 'L', 'H', 'X'),  -- Z
      ('U', 'X', '0', '1', 'W', 'W', 'W', 'W', 'X'),  -- W
      ('U', 'X', '0', '1', 'L', 'W', 'L', 'W', 'X'),  -- L
      ('U', 'X', '0', '1', 'H', 'W', 'W', 'H', 'X'),  -- H
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X')   -- -
    );

  -- AND: 0 dominates; L and H read as 0 and 1; anything else unknown.
  constant and_table : stdlogic_table := (
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'U', '0', 'U', 'U', 'U', '0', 'U', 'U'),  -- U
      ('U', 'X', '0', 'X', 'X', 'X', '0', 'X', 'X'),  -- X
      ('0', '0', '0', '0', '0', '0', '0', '0', '0'),  -- 0
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- 1
      ('U', 'X', '0', 'X', 'X', 'X', '0', 'X', 'X'),  -- Z
      ('U', 'X', '0', 'X', 'X', 'X', '0', 'X', 'X'),  -- W
      ('0', '0', '0', '0', '0', '0', '0', '0', '0'),  -- L
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- H
      ('U', 'X', '0', 'X', 'X', 'X', '0', 'X', 'X')   -- -
    );

  -- OR: 1 dominates.
  constant or_table : stdlogic_table := (
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'U', 'U', '1', 'U', 'U', 'U', '1', 'U'),  -- U
      ('U', 'X', 'X', '1', 'X', 'X', 'X', '1', 'X'),  -- X
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- 0
      ('1', '1', '1', '1', '1', '1', '1', '1', '1'),  -- 1
      ('U', 'X', 'X', '1', 'X', 'X', 'X', '1', 'X'),  -- Z
      ('U', 'X', 'X', '1', 'X', 'X', 'X', '1', 'X'),  -- W
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- L
      ('1', '1', '1', '1', '1', '1', '1', '1', '1'),  -- H
      ('U', 'X', 'X', '1', 'X', 'X', 'X', '1', 'X')   -- -
    );

  -- XOR: unknown whenever either input is.
  constant xor_table : stdlogic_table := (
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'U', 'U', 'U', 'U', 'U', 'U', 'U', 'U'),  -- U
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X'),  -- X
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- 0
      ('U', 'X', '1', '0', 'X', 'X', '1', '0', 'X'),  -- 1
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X'),  -- Z
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X'),  -- W
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X'),  -- L
      ('U', 'X', '1', '0', 'X', 'X', '1', '0', 'X'),  -- H
      ('U', 'X', 'X', 'X', 'X', 'X', 'X', 'X', 'X')   -- -
    );

  -- NOT
  constant not_table : stdlogic_1d :=
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'X', '1', '0', 'X', 'X', '1', '0', 'X');

  -- Strength stripping: weak values become forcing ones, everything else X.
  constant cvt_to_x01 : stdlogic_1d :=
    --  U    X    0    1    Z    W    L    H    -
      ('X', 'X', '0', '1', 'X', 'X', '0', '1', 'X');

  -- As cvt_to_x01, but Z stays Z.
  constant cvt_to_x01z : stdlogic_1d :=
    --  U    X    0    1    Z    W    L    H    -
      ('X', 'X', '0', '1', 'Z', 'X', '0', '1', 'X');

  -- As cvt_to_x01, but U stays U.
  constant cvt_to_ux01 : stdlogic_1d :=
    --  U    X    0    1    Z    W    L    H    -
      ('U', 'X', '0', '1', 'X', 'X', '0', '1', 'X');

  -------------------------------------------------------------------
  -- Resolution function
  -------------------------------------------------------------------
  function resolved (s : std_ulogic_vector) return std_ulogic is
    variable result : std_ulogic := 'Z';  -- the weakest state: no driver at all
  begin
    -- A single driver passes through unchanged (so that a lone '-' stays '-').
    if s'length = 1 then
      return s(s'low);
    end if;
    for i in s'range loop
      result := resolution_table(result, s(i));
    end loop;
    return result;
  end function resolved;

  -------------------------------------------------------------------
  -- Logical operators on single values
  -------------------------------------------------------------------
  function "and" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    -- and_table as rules (vams cannot index arrays by std_ulogic yet): a 0 wins, then a U.
    if l = '0' or l = 'L' or r = '0' or r = 'L' then
      return '0';
    elsif l = 'U' or r = 'U' then
      return 'U';
    elsif (l = '1' or l = 'H') and (r = '1' or r = 'H') then
      return '1';
    end if;
    return 'X';
  end function "and";

  function "nand" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    return not (l and r);
  end function "nand";

  function "or" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    -- or_table as rules: a 1 wins, then a U.
    if l = '1' or l = 'H' or r = '1' or r = 'H' then
      return '1';
    elsif l = 'U' or r = 'U' then
      return 'U';
    elsif (l = '0' or l = 'L') and (r = '0' or r = 'L') then
      return '0';
    end if;
    return 'X';
  end function "or";

  function "nor" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    return not (l or r);
  end function "nor";

  function "xor" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    -- xor_table as rules: U, then X for anything that is not a strong or weak 0 or 1.
    if l = 'U' or r = 'U' then
      return 'U';
    elsif to_x01(l) = 'X' or to_x01(r) = 'X' then
      return 'X';
    elsif to_x01(l) = to_x01(r) then
      return '0';
    end if;
    return '1';
  end function "xor";

  function "xnor" (l : std_ulogic; r : std_ulogic) return UX01 is
  begin
    return not (l xor r);
  end function "xnor";

  function "not" (l : std_ulogic) return UX01 is
  begin
    -- not_table as rules.
    if l = 'U' then
      return 'U';
    elsif l = '0' or l = 'L' then
      return '1';
    elsif l = '1' or l = 'H' then
      return '0';
    end if;
    return 'X';
  end function "not";

  -------------------------------------------------------------------
  -- Vectorized logical operators
  -------------------------------------------------------------------
  function "and" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""and"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) and rv(i);
    end loop;
    return result;
  end function "and";

  function "nand" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""nand"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) and rv(i));
    end loop;
    return result;
  end function "nand";

  function "or" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""or"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) or rv(i);
    end loop;
    return result;
  end function "or";

  function "nor" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""nor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) or rv(i));
    end loop;
    return result;
  end function "nor";

  function "xor" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""xor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xor rv(i);
    end loop;
    return result;
  end function "xor";

  function "xnor" (l, r : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    alias rv : std_logic_vector(1 to r'length) is r;
    variable result : std_logic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""xnor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) xor rv(i));
    end loop;
    return result;
  end function "xnor";

  function "not" (l : std_logic_vector) return std_logic_vector is
    alias lv : std_logic_vector(1 to l'length) is l;
    variable result : std_logic_vector(1 to l'length);
  begin
    for i in result'range loop
      result(i) := not lv(i);
    end loop;
    return result;
  end function "not";

  function "and" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""and"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) and rv(i);
    end loop;
    return result;
  end function "and";

  function "nand" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""nand"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) and rv(i));
    end loop;
    return result;
  end function "nand";

  function "or" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""or"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) or rv(i);
    end loop;
    return result;
  end function "or";

  function "nor" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""nor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) or rv(i));
    end loop;
    return result;
  end function "nor";

  function "xor" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""xor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := lv(i) xor rv(i);
    end loop;
    return result;
  end function "xor";

  function "xnor" (l, r : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    alias rv : std_ulogic_vector(1 to r'length) is r;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    assert l'length = r'length
      report "STD_LOGIC_1164.""xnor"": arguments are not of the same length"
      severity failure;
    for i in result'range loop
      result(i) := not (lv(i) xor rv(i));
    end loop;
    return result;
  end function "xnor";

  function "not" (l : std_ulogic_vector) return std_ulogic_vector is
    alias lv : std_ulogic_vector(1 to l'length) is l;
    variable result : std_ulogic_vector(1 to l'length);
  begin
    for i in result'range loop
      result(i) := not lv(i);
    end loop;
    return result;
  end function "not";

  -------------------------------------------------------------------
  -- Conversion functions
  -------------------------------------------------------------------
  function to_bit (s : std_ulogic; xmap : bit := '0') return bit is
  begin
    case s is
      when '0' | 'L' => return '0';
      when '1' | 'H' => return '1';
      when others    => return xmap;
    end case;
  end function to_bit;

  function to_bitvector (s : std_logic_vector; xmap : bit := '0') return bit_vector is
    alias sv : std_logic_vector(s'length - 1 downto 0) is s;
    variable result : bit_vector(s'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := to_bit(sv(i), xmap);
    end loop;
    return result;
  end function to_bitvector;

  function to_bitvector (s : std_ulogic_vector; xmap : bit := '0') return bit_vector is
    alias sv : std_ulogic_vector(s'length - 1 downto 0) is s;
    variable result : bit_vector(s'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := to_bit(sv(i), xmap);
    end loop;
    return result;
  end function to_bitvector;

  function to_stdulogic (b : bit) return std_ulogic is
  begin
    case b is
      when '0' => return '0';
      when '1' => return '1';
    end case;
  end function to_stdulogic;

  function to_stdlogicvector (b : bit_vector) return std_logic_vector is
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    variable result : std_logic_vector(b'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := to_stdulogic(bv(i));
    end loop;
    return result;
  end function to_stdlogicvector;

  function to_stdlogicvector (s : std_ulogic_vector) return std_logic_vector is
    alias sv : std_ulogic_vector(s'length - 1 downto 0) is s;
    variable result : std_logic_vector(s'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := sv(i);
    end loop;
    return result;
  end function to_stdlogicvector;

  function to_stdulogicvector (b : bit_vector) return std_ulogic_vector is
    alias bv : bit_vector(b'length - 1 downto 0) is b;
    variable result : std_ulogic_vector(b'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := to_stdulogic(bv(i));
    end loop;
    return result;
  end function to_stdulogicvector;

  function to_stdulogicvector (s : std_logic_vector) return std_ulogic_vector is
    alias sv : std_logic_vector(s'length - 1 downto 0) is s;
    variable result : std_ulogic_vector(s'length - 1 downto 0);
  begin
    for i in result'range loop
      result(i) := sv(i);
    end loop;
    return result;
  end function to_stdulogicvector;

  -------------------------------------------------------------------
  -- Strength strippers and type convertors
  -------------------------------------------------------------------
  function to_x01 (s : std_logic_vector) return std_logic_vector is
    alias sv : std_logic_vector(1 to s'length) is s;
    variable result : std_logic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_x01(sv(i));
    end loop;
    return result;
  end function to_x01;

  function to_x01 (s : std_ulogic_vector) return std_ulogic_vector is
    alias sv : std_ulogic_vector(1 to s'length) is s;
    variable result : std_ulogic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_x01(sv(i));
    end loop;
    return result;
  end function to_x01;

  function to_x01 (s : std_ulogic) return X01 is
  begin
    -- cvt_to_x01 as rules.
    if s = '0' or s = 'L' then
      return '0';
    elsif s = '1' or s = 'H' then
      return '1';
    end if;
    return 'X';
  end function to_x01;

  function to_x01 (b : bit_vector) return std_logic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_logic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_x01(bv(i));
    end loop;
    return result;
  end function to_x01;

  function to_x01 (b : bit_vector) return std_ulogic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_ulogic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_x01(bv(i));
    end loop;
    return result;
  end function to_x01;

  function to_x01 (b : bit) return X01 is
  begin
    case b is
      when '0' => return '0';
      when '1' => return '1';
    end case;
  end function to_x01;

  function to_x01z (s : std_logic_vector) return std_logic_vector is
    alias sv : std_logic_vector(1 to s'length) is s;
    variable result : std_logic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_x01z(sv(i));
    end loop;
    return result;
  end function to_x01z;

  function to_x01z (s : std_ulogic_vector) return std_ulogic_vector is
    alias sv : std_ulogic_vector(1 to s'length) is s;
    variable result : std_ulogic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_x01z(sv(i));
    end loop;
    return result;
  end function to_x01z;

  function to_x01z (s : std_ulogic) return X01Z is
  begin
    -- cvt_to_x01z as rules.
    if s = '0' or s = 'L' then
      return '0';
    elsif s = '1' or s = 'H' then
      return '1';
    elsif s = 'Z' then
      return 'Z';
    end if;
    return 'X';
  end function to_x01z;

  function to_x01z (b : bit_vector) return std_logic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_logic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_x01z(bv(i));
    end loop;
    return result;
  end function to_x01z;

  function to_x01z (b : bit_vector) return std_ulogic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_ulogic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_x01z(bv(i));
    end loop;
    return result;
  end function to_x01z;

  function to_x01z (b : bit) return X01Z is
  begin
    case b is
      when '0' => return '0';
      when '1' => return '1';
    end case;
  end function to_x01z;

  function to_ux01 (s : std_logic_vector) return std_logic_vector is
    alias sv : std_logic_vector(1 to s'length) is s;
    variable result : std_logic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_ux01(sv(i));
    end loop;
    return result;
  end function to_ux01;

  function to_ux01 (s : std_ulogic_vector) return std_ulogic_vector is
    alias sv : std_ulogic_vector(1 to s'length) is s;
    variable result : std_ulogic_vector(1 to s'length);
  begin
    for i in result'range loop
      result(i) := cvt_to_ux01(sv(i));
    end loop;
    return result;
  end function to_ux01;

  function to_ux01 (s : std_ulogic) return UX01 is
  begin
    -- cvt_to_ux01 as rules.
    if s = 'U' then
      return 'U';
    elsif s = '0' or s = 'L' then
      return '0';
    elsif s = '1' or s = 'H' then
      return '1';
    end if;
    return 'X';
  end function to_ux01;

  function to_ux01 (b : bit_vector) return std_logic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_logic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_ux01(bv(i));
    end loop;
    return result;
  end function to_ux01;

  function to_ux01 (b : bit_vector) return std_ulogic_vector is
    alias bv : bit_vector(1 to b'length) is b;
    variable result : std_ulogic_vector(1 to b'length);
  begin
    for i in result'range loop
      result(i) := to_ux01(bv(i));
    end loop;
    return result;
  end function to_ux01;

  function to_ux01 (b : bit) return UX01 is
  begin
    case b is
      when '0' => return '0';
      when '1' => return '1';
    end case;
  end function to_ux01;

  -------------------------------------------------------------------
  -- Edge detection
  -------------------------------------------------------------------
  function rising_edge (signal s : std_ulogic) return boolean is
  begin
    return s'event and to_x01(s) = '1' and to_x01(s'last_value) = '0';
  end function rising_edge;

  function falling_edge (signal s : std_ulogic) return boolean is
  begin
    return s'event and to_x01(s) = '0' and to_x01(s'last_value) = '1';
  end function falling_edge;

  -------------------------------------------------------------------
  -- Object contains an unknown
  -------------------------------------------------------------------
  function is_x (s : std_ulogic_vector) return boolean is
  begin
    for i in s'range loop
      if is_x(s(i)) then
        return true;
      end if;
    end loop;
    return false;
  end function is_x;

  function is_x (s : std_logic_vector) return boolean is
  begin
    for i in s'range loop
      if is_x(s(i)) then
        return true;
      end if;
    end loop;
    return false;
  end function is_x;

  function is_x (s : std_ulogic) return boolean is
  begin
    case s is
      when 'U' | 'X' | 'Z' | 'W' | '-' => return true;
      when others                      => return false;
    end case;
  end function is_x;

end package body std_logic_1164;
