entity e is end entity f;
