-- Array values whose length differs from their target's, where elaboration knows both
-- lengths (LRM 8.4, 8.5, 2.1.1.1): each is an error at the value, naming the target.
library ieee;
use ieee.numeric_std.all;

entity t is
end entity t;

architecture a of t is
  subtype word is bit_vector(7 downto 0);
  signal s : bit_vector(3 downto 0);
  signal init : bit_vector(3 downto 0) := "101";
  constant c : string(1 to 4) := "abc";

  function widen (x : bit_vector) return word is
  begin
    return x;
  end function widen;

  procedure get (o : out bit_vector(3 downto 0)) is
  begin
    o := "0000";
  end procedure get;
begin
  p : process is
    variable a, b : signed(4 downto 0) := "00011";
    variable v : signed(11 downto 0);
    variable w : bit_vector(7 downto 0);
    variable z : bit_vector(7 downto 0) := "0101";
    variable r : word;
  begin
    v := a * b;
    s <= "10101" after 2 ns;
    w(7 downto 4) := "11";
    r := widen("1010");
    get(w);
    wait;
  end process p;
end architecture a;
