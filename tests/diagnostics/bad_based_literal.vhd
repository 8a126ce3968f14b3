entity e is
  generic (n : integer := 16#FG#);
end entity e;
