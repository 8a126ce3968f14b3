-- VAMS.TABLES: tabulated functions, for quantities driven by measured or datasheet data.
-- Not an IEEE package: vams's own (library vams).
--
-- Every subprogram here is implemented natively by the simulator: like every
-- subprogram of a vams stdlib package that is declared without a body, it has
-- none, and there is no package body.

package tables is

  -- The piecewise-linear function of TABLE at X. TABLE holds x, y pairs as SPICE's PWL
  -- source writes them, (x0, y0, x1, y1, ...), with x0 < x1 < ...: linear between
  -- neighbouring points, constant beyond the first and the last (continuous: a jump is a
  -- steep segment). A source driven by a table of times, whose corners the solver steps to:
  --   v == pwl(drive, now);
  -- In a simultaneous statement TABLE must be a constant or a generic (`vams fit --drive`
  -- fills a real_vector generic from a capture's column).
  function pwl (table : real_vector; x : real) return real;

end package tables;
