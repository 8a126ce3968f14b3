-- IEEE.MECHANICAL_SYSTEMS for vams: translational and rotational natures (IEEE Std 1076.1.1).

library ieee;
use ieee.fundamental_constants.all;

package mechanical_systems is

  -- Scalar subtypes, each with its tolerance group
  subtype displacement         is real tolerance "DEFAULT_DISPLACEMENT";
  subtype force                is real tolerance "DEFAULT_FORCE";
  subtype velocity             is real tolerance "DEFAULT_VELOCITY";
  subtype acceleration         is real tolerance "DEFAULT_ACCELERATION";
  subtype mass                 is real tolerance "DEFAULT_MASS";
  subtype stiffness            is real tolerance "DEFAULT_STIFFNESS";
  subtype damping              is real tolerance "DEFAULT_DAMPING";
  subtype momentum             is real tolerance "DEFAULT_MOMENTUM";
  subtype angle                is real tolerance "DEFAULT_ANGLE";
  subtype torque               is real tolerance "DEFAULT_TORQUE";
  subtype angular_velocity     is real tolerance "DEFAULT_ANGULAR_VELOCITY";
  subtype angular_acceleration is real tolerance "DEFAULT_ANGULAR_ACCELERATION";
  subtype moment_inertia       is real tolerance "DEFAULT_MOMENT_INERTIA";
  subtype angular_momentum     is real tolerance "DEFAULT_ANGULAR_MOMENTUM";
  subtype angular_stiffness    is real tolerance "DEFAULT_ANGULAR_STIFFNESS";
  subtype angular_damping      is real tolerance "DEFAULT_ANGULAR_DAMPING";
  -- The drafts of 1076.1.1 (used as library `ieee_proposed`, as in The System Designer's
  -- Guide to VHDL-AMS) named the moment of inertia `mmoment_i`; models written against them
  -- still use it.
  subtype mmoment_i            is moment_inertia;

  -- Units, spelt out
  attribute unit of displacement         : subtype is "meter";
  attribute unit of force                : subtype is "newton";
  attribute unit of velocity             : subtype is "meter/second";
  attribute unit of acceleration         : subtype is "meter/second^2";
  attribute unit of mass                 : subtype is "kilogram";
  attribute unit of stiffness            : subtype is "newton/meter";
  attribute unit of damping              : subtype is "newton*second/meter";
  attribute unit of momentum             : subtype is "kilogram*meter/second";
  attribute unit of angle                : subtype is "radian";
  attribute unit of torque               : subtype is "newton*meter";
  attribute unit of angular_velocity     : subtype is "radian/second";
  attribute unit of angular_acceleration : subtype is "radian/second^2";
  attribute unit of moment_inertia       : subtype is "kilogram*meter^2";
  attribute unit of angular_momentum     : subtype is "kilogram*meter^2/second";
  attribute unit of angular_stiffness    : subtype is "newton*meter/radian";
  attribute unit of angular_damping      : subtype is "newton*meter*second/radian";

  -- Units, abbreviated
  attribute symbol of displacement         : subtype is "m";
  attribute symbol of force                : subtype is "N";
  attribute symbol of velocity             : subtype is "m/s";
  attribute symbol of acceleration         : subtype is "m/s^2";
  attribute symbol of mass                 : subtype is "kg";
  attribute symbol of stiffness            : subtype is "N/m";
  attribute symbol of damping              : subtype is "N*s/m";
  attribute symbol of momentum             : subtype is "kg*m/s";
  attribute symbol of angle                : subtype is "rad";
  attribute symbol of torque               : subtype is "N*m";
  attribute symbol of angular_velocity     : subtype is "rad/s";
  attribute symbol of angular_acceleration : subtype is "rad/s^2";
  attribute symbol of moment_inertia       : subtype is "kg*m^2";
  attribute symbol of angular_momentum     : subtype is "kg*m^2/s";
  attribute symbol of angular_stiffness    : subtype is "N*m/rad";
  attribute symbol of angular_damping      : subtype is "N*m*s/rad";

  -- Natures. Each mechanical domain comes in two forms: with position (or
  -- angle) as the across quantity, and with velocity (or angular velocity).
  nature translational is
    displacement across
    force        through
    translational_ref reference;

  nature translational_vector is array (natural range <>) of translational;

  nature translational_velocity is
    velocity across
    force    through
    translational_velocity_ref reference;

  nature translational_velocity_vector is array (natural range <>) of translational_velocity;

  nature rotational is
    angle  across
    torque through
    rotational_ref reference;

  nature rotational_vector is array (natural range <>) of rotational;

  nature rotational_velocity is
    angular_velocity across
    torque           through
    rotational_velocity_ref reference;

  nature rotational_velocity_vector is array (natural range <>) of rotational_velocity;

  -- Vector subtypes: those of the natures' quantities ...
  subtype displacement_vector     is translational_vector'across;
  subtype force_vector            is translational_vector'through;
  subtype velocity_vector         is translational_velocity_vector'across;
  subtype force_velocity_vector   is translational_velocity_vector'through;
  subtype angle_vector            is rotational_vector'across;
  subtype torque_vector           is rotational_vector'through;
  subtype angular_velocity_vector is rotational_velocity_vector'across;
  subtype torque_velocity_vector  is rotational_velocity_vector'through;

  -- ... and the others
  subtype acceleration_vector         is real_vector tolerance "DEFAULT_ACCELERATION";
  subtype mass_vector                 is real_vector tolerance "DEFAULT_MASS";
  subtype stiffness_vector            is real_vector tolerance "DEFAULT_STIFFNESS";
  subtype damping_vector              is real_vector tolerance "DEFAULT_DAMPING";
  subtype momentum_vector             is real_vector tolerance "DEFAULT_MOMENTUM";
  subtype angular_acceleration_vector is real_vector tolerance "DEFAULT_ANGULAR_ACCELERATION";
  subtype moment_inertia_vector       is real_vector tolerance "DEFAULT_MOMENT_INERTIA";
  subtype angular_momentum_vector     is real_vector tolerance "DEFAULT_ANGULAR_MOMENTUM";
  subtype angular_stiffness_vector    is real_vector tolerance "DEFAULT_ANGULAR_STIFFNESS";
  subtype angular_damping_vector      is real_vector tolerance "DEFAULT_ANGULAR_DAMPING";

  -- The fixed frame of reference of translational systems
  alias anchor is translational_ref;

  -- Short names used by most published models (and by the pre-standard
  -- ieee_proposed package, where TRANSLATIONAL_V and ROTATIONAL_V were natures
  -- of their own): the same natures and reference terminals under other names.
  subnature translational_v is translational_velocity;
  subnature rotational_v    is rotational_velocity;
  subnature translational_v_vector is translational_velocity_vector;
  subnature rotational_v_vector    is rotational_velocity_vector;

  alias translational_v_ref is translational_velocity_ref;
  alias rotational_v_ref    is rotational_velocity_ref;

end package mechanical_systems;
