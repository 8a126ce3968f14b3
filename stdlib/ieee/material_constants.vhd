-- IEEE.MATERIAL_CONSTANTS for vams: material and ambient constants (IEEE Std 1076.1.1).
--
-- The constants are deferred: the standard fixes their names, and the values,
-- which are measured and depend on the application, are given in the package
-- body below, where a project may change them.

package material_constants is

  constant phys_eps_si   : real;  -- relative permittivity of silicon
  constant phys_eps_sio2 : real;  -- relative permittivity of silicon dioxide
  constant phys_e_si     : real;  -- Young's modulus of silicon [Pa]
  constant phys_e_sio2   : real;  -- Young's modulus of silicon dioxide [Pa]
  constant phys_e_poly   : real;  -- Young's modulus of polysilicon [Pa]
  constant phys_nu_si    : real;  -- Poisson's ratio of silicon, <100> orientation
  constant phys_nu_poly  : real;  -- Poisson's ratio of polysilicon, <100> orientation
  constant phys_rho_poly : real;  -- density of polysilicon [kg/m^3]
  constant phys_rho_sio2 : real;  -- density of silicon dioxide [kg/m^3]

  -- Environment
  constant ambient_temperature : real;  -- [K]
  constant ambient_pressure    : real;  -- [Pa]
  constant ambient_illuminance : real;  -- [lx]

end package material_constants;

package body material_constants is

  constant phys_eps_si   : real := 11.7;
  constant phys_eps_sio2 : real := 3.9;
  constant phys_e_si     : real := 190.0e+9;
  constant phys_e_sio2   : real := 73.0e+9;
  constant phys_e_poly   : real := 1.62e+9;
  constant phys_nu_si    : real := 0.28;
  constant phys_nu_poly  : real := 0.22;
  constant phys_rho_poly : real := 2330.0;
  constant phys_rho_sio2 : real := 2220.0;

  constant ambient_temperature : real := 298.15;     -- 25 degrees Celsius
  constant ambient_pressure    : real := 100_000.0;  -- 1 bar
  constant ambient_illuminance : real := 30_000.0;   -- daylight

end package body material_constants;
