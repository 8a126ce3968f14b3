-- Conversion functions in port maps (VHDL-93 style) are not supported yet: each gets a
-- located diagnostic with the workaround.
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
  u1 : entity work.inverter port map ( a => to_bit(b), y => y );
  u2 : entity work.inverter port map ( a => y, to_bool(y) => yb );
end architecture test;
