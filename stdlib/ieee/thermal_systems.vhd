-- IEEE.THERMAL_SYSTEMS for vams: thermal subtypes and the THERMAL nature (IEEE Std 1076.1.1).

library ieee;
use ieee.fundamental_constants.all;

package thermal_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype temperature         is real tolerance "DEFAULT_TEMPERATURE";
  subtype heat_flow           is real tolerance "DEFAULT_HEAT_FLOW";
  subtype thermal_capacitance is real tolerance "DEFAULT_THERMAL_CAPACITANCE";
  subtype thermal_resistance  is real tolerance "DEFAULT_THERMAL_RESISTANCE";
  subtype thermal_conductance is real tolerance "DEFAULT_THERMAL_CONDUCTANCE";

  -- Units, spelt out
  attribute unit of temperature         : subtype is "kelvin";
  attribute unit of heat_flow           : subtype is "watt";
  attribute unit of thermal_capacitance : subtype is "joule/kelvin";
  attribute unit of thermal_resistance  : subtype is "kelvin/watt";
  attribute unit of thermal_conductance : subtype is "watt/kelvin";

  -- Units, abbreviated
  attribute symbol of temperature         : subtype is "K";
  attribute symbol of heat_flow           : subtype is "W";
  attribute symbol of thermal_capacitance : subtype is "J/K";
  attribute symbol of thermal_resistance  : subtype is "K/W";
  attribute symbol of thermal_conductance : subtype is "W/K";

  -- Nature: temperature across, heat flow through
  nature thermal is
    temperature across
    heat_flow   through
    thermal_ref reference;

  nature thermal_vector is array (natural range <>) of thermal;

  -- Vector subtypes
  subtype temperature_vector         is thermal_vector'across;
  subtype heat_flow_vector           is thermal_vector'through;
  subtype thermal_capacitance_vector is real_vector tolerance "DEFAULT_THERMAL_CAPACITANCE";
  subtype thermal_resistance_vector  is real_vector tolerance "DEFAULT_THERMAL_RESISTANCE";
  subtype thermal_conductance_vector is real_vector tolerance "DEFAULT_THERMAL_CONDUCTANCE";

end package thermal_systems;
