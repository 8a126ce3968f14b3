-- STD.ENV for vams: stopping the simulation from a model, and the simulator's time resolution.
--
-- Every subprogram here is implemented natively by the simulator: like every
-- subprogram of a vams stdlib package that is declared without a body, it has
-- none, and there is no package body.

package env is

  -- End the simulation run as if it had been interrupted; STATUS, where given,
  -- is reported to the caller of the simulator (its exit status).
  procedure stop (status : integer);
  procedure stop;

  -- End the simulation run for good; STATUS as for STOP.
  procedure finish (status : integer);
  procedure finish;

  -- The resolution limit of TIME: the smallest representable time step (1 fs in vams).
  function resolution_limit return delay_length;

end package env;
