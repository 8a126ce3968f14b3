-- IEEE.FLUIDIC_SYSTEMS for vams: fluidic subtypes and natures (IEEE Std 1076.1.1).
--
-- Both natures have pressure as the across quantity. FLUIDIC assumes an
-- incompressible medium and has volume flow rate as the through quantity;
-- COMPRESSIBLE_FLUIDIC has mass flow rate. Subtypes prefixed CF belong to the
-- compressible nature.

library ieee;
use ieee.fundamental_constants.all;

package fluidic_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype pressure       is real tolerance "DEFAULT_PRESSURE";
  subtype vflow_rate     is real tolerance "DEFAULT_VFLOW_RATE";
  subtype mass_flow_rate is real tolerance "DEFAULT_MASS_FLOW_RATE";
  subtype volume         is real tolerance "DEFAULT_VOLUME";
  subtype density        is real tolerance "DEFAULT_DENSITY";
  subtype viscosity      is real tolerance "DEFAULT_VISCOSITY";
  subtype fresistance    is real tolerance "DEFAULT_FRESISTANCE";
  subtype fconductance   is real tolerance "DEFAULT_FCONDUCTANCE";
  subtype fcapacitance   is real tolerance "DEFAULT_FCAPACITANCE";
  subtype inertance      is real tolerance "DEFAULT_INERTANCE";
  subtype cfresistance   is real tolerance "DEFAULT_CFRESISTANCE";
  subtype cfcapacitance  is real tolerance "DEFAULT_CFCAPACITANCE";
  subtype cfinertance    is real tolerance "DEFAULT_CFINERTANCE";
  subtype cfconductance  is real tolerance "DEFAULT_CFCONDUCTANCE";

  -- Units, spelt out
  attribute unit of pressure       : subtype is "pascal";
  attribute unit of vflow_rate     : subtype is "meter^3/second";
  attribute unit of mass_flow_rate : subtype is "kilogram/second";
  attribute unit of volume         : subtype is "meter^3";
  attribute unit of density        : subtype is "kilogram/meter^3";
  attribute unit of viscosity      : subtype is "pascal*second";
  attribute unit of fresistance    : subtype is "pascal*second/meter^3";
  attribute unit of fconductance   : subtype is "meter^3/(pascal*second)";
  attribute unit of fcapacitance   : subtype is "meter^3/pascal";
  attribute unit of inertance      : subtype is "pascal*second^2/meter^3";
  attribute unit of cfresistance   : subtype is "pascal*second/kilogram";
  attribute unit of cfcapacitance  : subtype is "kilogram/pascal";
  attribute unit of cfinertance    : subtype is "pascal*second^2/kilogram";
  attribute unit of cfconductance  : subtype is "kilogram/(pascal*second)";

  -- Units, abbreviated
  attribute symbol of pressure       : subtype is "Pa";
  attribute symbol of vflow_rate     : subtype is "m^3/s";
  attribute symbol of mass_flow_rate : subtype is "kg/s";
  attribute symbol of volume         : subtype is "m^3";
  attribute symbol of density        : subtype is "kg/m^3";
  attribute symbol of viscosity      : subtype is "Pa*s";
  attribute symbol of fresistance    : subtype is "Pa*s/m^3";
  attribute symbol of fconductance   : subtype is "m^3/(Pa*s)";
  attribute symbol of fcapacitance   : subtype is "m^3/Pa";
  attribute symbol of inertance      : subtype is "Pa*s^2/m^3";
  attribute symbol of cfresistance   : subtype is "Pa*s/kg";
  attribute symbol of cfcapacitance  : subtype is "kg/Pa";
  attribute symbol of cfinertance    : subtype is "Pa*s^2/kg";
  attribute symbol of cfconductance  : subtype is "kg/(Pa*s)";

  -- Natures
  nature fluidic is
    pressure   across
    vflow_rate through
    fluidic_ref reference;

  nature fluidic_vector is array (natural range <>) of fluidic;

  nature compressible_fluidic is
    pressure       across
    mass_flow_rate through
    compressible_fluidic_ref reference;

  nature compressible_fluidic_vector is array (natural range <>) of compressible_fluidic;

  -- Vector subtypes: those of the natures' quantities ...
  subtype pressure_vector       is fluidic_vector'across;
  subtype vflow_rate_vector     is fluidic_vector'through;
  subtype mass_flow_rate_vector is compressible_fluidic_vector'through;

  -- ... and the others
  subtype volume_vector        is real_vector tolerance "DEFAULT_VOLUME";
  subtype density_vector       is real_vector tolerance "DEFAULT_DENSITY";
  subtype viscosity_vector     is real_vector tolerance "DEFAULT_VISCOSITY";
  subtype fresistance_vector   is real_vector tolerance "DEFAULT_FRESISTANCE";
  subtype fconductance_vector  is real_vector tolerance "DEFAULT_FCONDUCTANCE";
  subtype fcapacitance_vector  is real_vector tolerance "DEFAULT_FCAPACITANCE";
  subtype inertance_vector     is real_vector tolerance "DEFAULT_INERTANCE";
  subtype cfresistance_vector  is real_vector tolerance "DEFAULT_CFRESISTANCE";
  subtype cfconductance_vector is real_vector tolerance "DEFAULT_CFCONDUCTANCE";
  subtype cfcapacitance_vector is real_vector tolerance "DEFAULT_CFCAPACITANCE";
  subtype cfinertance_vector   is real_vector tolerance "DEFAULT_CFINERTANCE";

end package fluidic_systems;
