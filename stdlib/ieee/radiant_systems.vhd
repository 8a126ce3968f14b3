-- IEEE.RADIANT_SYSTEMS for vams: photometric subtypes and the RADIANT nature (IEEE Std 1076.1.1).

library ieee;
use ieee.fundamental_constants.all;

package radiant_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype illuminance        is real tolerance "DEFAULT_ILLUMINANCE";
  subtype luminous_flux      is real tolerance "DEFAULT_LUMINOUS_FLUX";
  subtype luminous_intensity is real tolerance "DEFAULT_LUMINOUS_INTENSITY";
  subtype irradiance         is real tolerance "DEFAULT_IRRADIANCE";

  -- Units, spelt out
  attribute unit of illuminance        : subtype is "lux";
  attribute unit of luminous_flux      : subtype is "lumen";
  attribute unit of luminous_intensity : subtype is "candela";
  attribute unit of irradiance         : subtype is "watt/meter^2";

  -- Units, abbreviated
  attribute symbol of illuminance        : subtype is "lx";
  attribute symbol of luminous_flux      : subtype is "lm";
  attribute symbol of luminous_intensity : subtype is "cd";
  attribute symbol of irradiance         : subtype is "W/m^2";

  -- Nature: luminous intensity across, luminous flux through
  nature radiant is
    luminous_intensity across
    luminous_flux      through
    radiant_ref reference;

  nature radiant_vector is array (natural range <>) of radiant;

  -- Vector subtypes
  subtype luminous_intensity_vector is radiant_vector'across;
  subtype luminous_flux_vector      is radiant_vector'through;
  subtype illuminance_vector        is real_vector tolerance "DEFAULT_ILLUMINANCE";
  subtype irradiance_vector         is real_vector tolerance "DEFAULT_IRRADIANCE";

end package radiant_systems;
