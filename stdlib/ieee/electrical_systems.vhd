-- IEEE.ELECTRICAL_SYSTEMS for vams: electrical and magnetic natures (IEEE Std 1076.1.1).

library ieee;
use ieee.fundamental_constants.all;

package electrical_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype voltage                 is real tolerance "DEFAULT_VOLTAGE";
  subtype current                 is real tolerance "DEFAULT_CURRENT";
  subtype charge                  is real tolerance "DEFAULT_CHARGE";
  subtype resistance              is real tolerance "DEFAULT_RESISTANCE";
  subtype conductance             is real tolerance "DEFAULT_CONDUCTANCE";
  subtype capacitance             is real tolerance "DEFAULT_CAPACITANCE";
  subtype mmf                     is real tolerance "DEFAULT_MMF";
  subtype electric_flux           is real tolerance "DEFAULT_FLUX";
  subtype electric_flux_density   is real tolerance "DEFAULT_FLUX_DENSITY";
  subtype electric_field_strength is real tolerance "DEFAULT_FIELD_STRENGTH";
  subtype magnetic_flux           is real tolerance "DEFAULT_FLUX";
  subtype magnetic_flux_density   is real tolerance "DEFAULT_FLUX_DENSITY";
  subtype magnetic_field_strength is real tolerance "DEFAULT_FIELD_STRENGTH";
  subtype inductance              is real tolerance "DEFAULT_INDUCTANCE";
  subtype reluctance              is real tolerance "DEFAULT_RELUCTANCE";

  -- vams addition: the pre-standard (ieee_proposed) name of MAGNETIC_FLUX
  subtype flux is magnetic_flux;

  -- Units, spelt out
  attribute unit of voltage                 : subtype is "volt";
  attribute unit of current                 : subtype is "ampere";
  attribute unit of charge                  : subtype is "coulomb";
  attribute unit of resistance              : subtype is "ohm";
  attribute unit of conductance             : subtype is "siemens";
  attribute unit of capacitance             : subtype is "farad";
  attribute unit of mmf                     : subtype is "ampere";
  attribute unit of electric_flux           : subtype is "coulomb";
  attribute unit of electric_flux_density   : subtype is "coulomb/meter^2";
  attribute unit of electric_field_strength : subtype is "volt/meter";
  attribute unit of magnetic_flux           : subtype is "weber";
  attribute unit of magnetic_flux_density   : subtype is "tesla";
  attribute unit of magnetic_field_strength : subtype is "ampere/meter";
  attribute unit of inductance              : subtype is "henry";
  attribute unit of reluctance              : subtype is "ampere/weber";

  -- Units, abbreviated
  attribute symbol of voltage                 : subtype is "V";
  attribute symbol of current                 : subtype is "A";
  attribute symbol of charge                  : subtype is "C";
  attribute symbol of resistance              : subtype is "Ohm";
  attribute symbol of conductance             : subtype is "S";
  attribute symbol of capacitance             : subtype is "F";
  attribute symbol of mmf                     : subtype is "A";
  attribute symbol of electric_flux           : subtype is "C";
  attribute symbol of electric_flux_density   : subtype is "C/m^2";
  attribute symbol of electric_field_strength : subtype is "V/m";
  attribute symbol of magnetic_flux           : subtype is "Wb";
  attribute symbol of magnetic_flux_density   : subtype is "T";
  attribute symbol of magnetic_field_strength : subtype is "A/m";
  attribute symbol of inductance              : subtype is "H";
  attribute symbol of reluctance              : subtype is "A/Wb";

  -- Natures: a terminal of nature ELECTRICAL has a voltage across it (to the
  -- reference terminal ELECTRICAL_REF) and a current through it.
  nature electrical is
    voltage across
    current through
    electrical_ref reference;

  nature electrical_vector is array (natural range <>) of electrical;

  nature magnetic is
    mmf           across
    magnetic_flux through
    magnetic_ref reference;

  nature magnetic_vector is array (natural range <>) of magnetic;

  -- Vector subtypes: those of the natures' quantities ...
  subtype voltage_vector       is electrical_vector'across;
  subtype current_vector       is electrical_vector'through;
  subtype mmf_vector           is magnetic_vector'across;
  subtype magnetic_flux_vector is magnetic_vector'through;

  -- ... and the others
  subtype charge_vector                  is real_vector tolerance "DEFAULT_CHARGE";
  subtype resistance_vector              is real_vector tolerance "DEFAULT_RESISTANCE";
  subtype conductance_vector             is real_vector tolerance "DEFAULT_CONDUCTANCE";
  subtype capacitance_vector             is real_vector tolerance "DEFAULT_CAPACITANCE";
  subtype electric_flux_vector           is real_vector tolerance "DEFAULT_FLUX";
  subtype electric_flux_density_vector   is real_vector tolerance "DEFAULT_FLUX_DENSITY";
  subtype electric_field_strength_vector is real_vector tolerance "DEFAULT_FIELD_STRENGTH";
  subtype magnetic_flux_density_vector   is real_vector tolerance "DEFAULT_FLUX_DENSITY";
  subtype magnetic_field_strength_vector is real_vector tolerance "DEFAULT_FIELD_STRENGTH";
  subtype inductance_vector              is real_vector tolerance "DEFAULT_INDUCTANCE";
  subtype reluctance_vector              is real_vector tolerance "DEFAULT_RELUCTANCE";

  -- The electrical reference terminal (circuit ground)
  alias ground is electrical_ref;

end package electrical_systems;
