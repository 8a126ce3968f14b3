entity e is
  port (a : in bit)
end entity e;
