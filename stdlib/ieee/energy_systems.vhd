-- IEEE.ENERGY_SYSTEMS for vams: energy and power subtypes, UNSPECIFIED nature (IEEE Std 1076.1.1).

library ieee;
use ieee.fundamental_constants.all;

package energy_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype energy       is real tolerance "DEFAULT_ENERGY";
  subtype power        is real tolerance "DEFAULT_POWER";
  subtype periodicity  is real tolerance "DEFAULT_PERIODICITY";
  subtype real_across  is real tolerance "DEFAULT_REAL_ACROSS";
  subtype real_through is real tolerance "DEFAULT_REAL_THROUGH";

  -- Units
  attribute unit   of energy : subtype is "joule";
  attribute unit   of power  : subtype is "watt";
  attribute symbol of energy : subtype is "J";
  attribute symbol of power  : subtype is "W";

  -- A nature for quantities of no particular physical domain
  nature unspecified is
    real_across  across
    real_through through
    unspecified_ref reference;

  nature unspecified_vector is array (natural range <>) of unspecified;

  -- Vector subtypes
  subtype energy_vector       is real_vector tolerance "DEFAULT_ENERGY";
  subtype power_vector        is real_vector tolerance "DEFAULT_POWER";
  subtype periodicity_vector  is real_vector tolerance "DEFAULT_PERIODICITY";
  subtype real_across_vector  is unspecified_vector'across;
  subtype real_through_vector is unspecified_vector'through;

  -- The drafts of 1076.1.1 (the `ieee_proposed` library of The System Designer's Guide)
  -- declared Boltzmann's constant and the elementary charge here, and textbook diode and
  -- noise models use them from this package (`vt == temp * K / Q;`).
  constant k : real := phys_k;          -- Boltzmann's constant [J/K]
  constant q : real := phys_q;          -- elementary charge [C]

end package energy_systems;
