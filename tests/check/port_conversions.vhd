-- Conversions in port maps that VHDL refuses or vams cannot combine: the actual of a
-- converted `out` port driven by a process too (two sources), and a conversion on the
-- formal of an `in` port (it converts on the actual side).
entity inverter is
  port ( a : in bit;  y : out bit );
end entity inverter;

architecture behavioral of inverter is
begin
  y <= not a;
end architecture behavioral;

entity port_conversions is
end entity port_conversions;

architecture test of port_conversions is
  function to_bit ( x : boolean ) return bit is
  begin
    if x then
      return '1';
    end if;
    return '0';
  end function to_bit;
  function to_bool ( x : bit ) return boolean is
  begin
    return x = '1';
  end function to_bool;
  signal b, yb : boolean;
  signal y : bit;
begin
  u1 : entity work.inverter port map ( a => to_bit(b), to_bool(y) => yb );
  u2 : entity work.inverter port map ( to_bool(a) => b, y => y );
  yb <= true after 5 ns;
end architecture test;
