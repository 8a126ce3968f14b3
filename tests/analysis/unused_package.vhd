-- A package nothing uses, with a misspelt constant in a declaration.
package limits is
  constant vmax : real := 16.0;
  constant vmin : real := -vmaxx;
end package limits;

entity alone is
end entity alone;

architecture a of alone is
begin
end architecture a;
