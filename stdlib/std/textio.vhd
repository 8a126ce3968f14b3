-- STD.TEXTIO for vams: line-oriented text input and output (VHDL-2002, plus hex/octal I/O).
--
-- Every subprogram here is implemented natively by the simulator: like every
-- subprogram of a vams stdlib package that is declared without a body, it has
-- none, and there is no package body. The formats follow LRM 14.3: READ skips
-- leading whitespace and returns GOOD = false (or, without GOOD, reports an
-- error) when the text does not hold a value of the type; WRITE appends the
-- value's image to the line, padded to FIELD characters on the JUSTIFIED side.
-- DEALLOCATE (for LINE) and ENDFILE (for TEXT) are the implicitly declared
-- operations of the access and file types.

package textio is

  -- Types and subtypes

  type line is access string;           -- a line of text, built up or consumed piecewise
  type text is file of string;          -- a text file; each element is one line

  type side is (right, left);           -- which side of the field a value is justified to

  subtype width is natural;             -- the width of a field, in characters

  -- The standard text files

  file input  : text open read_mode  is "STD_INPUT";
  file output : text open write_mode is "STD_OUTPUT";

  -- Input routines

  procedure readline (file f : text; l : inout line);

  procedure read (l : inout line; value : out bit;        good : out boolean);
  procedure read (l : inout line; value : out bit);

  procedure read (l : inout line; value : out bit_vector; good : out boolean);
  procedure read (l : inout line; value : out bit_vector);

  procedure read (l : inout line; value : out boolean;    good : out boolean);
  procedure read (l : inout line; value : out boolean);

  procedure read (l : inout line; value : out character;  good : out boolean);
  procedure read (l : inout line; value : out character);

  procedure read (l : inout line; value : out integer;    good : out boolean);
  procedure read (l : inout line; value : out integer);

  procedure read (l : inout line; value : out real;       good : out boolean);
  procedure read (l : inout line; value : out real);

  -- READ of a STRING takes exactly value'length characters, whitespace included.
  procedure read (l : inout line; value : out string;     good : out boolean);
  procedure read (l : inout line; value : out string);

  procedure read (l : inout line; value : out time;       good : out boolean);
  procedure read (l : inout line; value : out time);

  -- A BIT_VECTOR written as hexadecimal (4 bits a digit) or octal (3 bits a digit);
  -- underscores between digits are allowed.
  procedure hread (l : inout line; value : out bit_vector; good : out boolean);
  procedure hread (l : inout line; value : out bit_vector);

  procedure oread (l : inout line; value : out bit_vector; good : out boolean);
  procedure oread (l : inout line; value : out bit_vector);

  -- Output routines

  procedure writeline (file f : text; l : inout line);

  procedure write (l : inout line; value : in bit;
                   justified : in side := right; field : in width := 0);

  procedure write (l : inout line; value : in bit_vector;
                   justified : in side := right; field : in width := 0);

  procedure write (l : inout line; value : in boolean;
                   justified : in side := right; field : in width := 0);

  procedure write (l : inout line; value : in character;
                   justified : in side := right; field : in width := 0);

  procedure write (l : inout line; value : in integer;
                   justified : in side := right; field : in width := 0);

  -- DIGITS = 0 writes the value in exponential form (as REAL'IMAGE does);
  -- DIGITS > 0 writes it in fixed-point form with that many digits after the point.
  procedure write (l : inout line; value : in real;
                   justified : in side := right; field : in width := 0;
                   digits : in natural := 0);

  procedure write (l : inout line; value : in string;
                   justified : in side := right; field : in width := 0);

  -- The value is written as a multiple of UNIT, followed by the unit's name.
  procedure write (l : inout line; value : in time;
                   justified : in side := right; field : in width := 0;
                   unit : in time := ns);

  procedure hwrite (l : inout line; value : in bit_vector;
                    justified : in side := right; field : in width := 0);

  procedure owrite (l : inout line; value : in bit_vector;
                    justified : in side := right; field : in width := 0);

end package textio;
