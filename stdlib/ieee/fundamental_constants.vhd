-- IEEE.FUNDAMENTAL_CONSTANTS for vams: physical constants and SI prefixes (IEEE Std 1076.1.1).
--
-- The values are those of IEEE Std 1076.1.1 (CODATA 1998), so that published
-- models give the published results; they differ from the exact 2019 SI values
-- in the seventh significant digit at most. UNIT and SYMBOL are the attributes
-- that the discipline packages use to label each subtype with its SI unit.

library ieee;
use ieee.math_real.all;

package fundamental_constants is

  -- Unit of a subtype, spelt out ("volt") and abbreviated ("V")
  attribute unit   : string;
  attribute symbol : string;

  -- Physical constants
  constant phys_q           : real := 1.602_176_462e-19;  -- elementary charge [C]
  constant phys_eps0        : real := 8.854_187_817e-12;  -- permittivity of vacuum [F/m]
  constant phys_mu0         : real := 4.0e-7 * math_pi;   -- permeability of vacuum [H/m]
  constant phys_k           : real := 1.380_650_3e-23;    -- Boltzmann's constant [J/K]
  constant phys_gravity     : real := 9.806_65;           -- standard gravity [m/s^2]
  constant phys_ctok        : real := 273.15;             -- degrees Celsius to kelvin offset [K]
  constant phys_c           : real := 299_792_458.0;      -- speed of light in vacuum [m/s]
  constant phys_h           : real := 6.626_068_76e-34;   -- Planck's constant [J*s]
  constant phys_h_over_2_pi : real := phys_h / math_2_pi; -- reduced Planck's constant [J*s]

  -- SI scaling prefixes
  constant yocto : real := 1.0e-24;
  constant zepto : real := 1.0e-21;
  constant atto  : real := 1.0e-18;
  constant femto : real := 1.0e-15;
  constant pico  : real := 1.0e-12;
  constant nano  : real := 1.0e-9;
  constant micro : real := 1.0e-6;
  constant milli : real := 1.0e-3;
  constant centi : real := 1.0e-2;
  constant deci  : real := 1.0e-1;
  constant deka  : real := 1.0e+1;
  constant hecto : real := 1.0e+2;
  constant kilo  : real := 1.0e+3;
  constant mega  : real := 1.0e+6;
  constant giga  : real := 1.0e+9;
  constant tera  : real := 1.0e+12;
  constant peta  : real := 1.0e+15;
  constant exa   : real := 1.0e+18;
  constant zetta : real := 1.0e+21;
  constant yotta : real := 1.0e+24;

  alias deca is deka;

end package fundamental_constants;
