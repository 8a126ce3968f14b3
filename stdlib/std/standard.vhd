-- STD.STANDARD for vams: the predefined types of VHDL-2002 plus the IEEE 1076.1-2007 additions.
--
-- Source text is UTF-8; the upper half of CHARACTER is ISO 8859-1 (Latin-1), so each
-- literal such as 'é' below is the character at that Latin-1 position.
--
-- The predefined operators ("=", "<", "+", "and", "&", ...) and the predefined
-- attributes are not written here: the compiler declares them implicitly for each
-- type, right after its type declaration, as the LRM requires.
-- NOW (both forms) and FREQUENCY have no body: the simulator implements them.

package standard is

  type boolean is (false, true);

  type bit is ('0', '1');

  type character is (
    nul, soh, stx, etx, eot, enq, ack, bel,  --   0 ..   7
    bs,  ht,  lf,  vt,  ff,  cr,  so,  si,   --   8 ..  15
    dle, dc1, dc2, dc3, dc4, nak, syn, etb,  --  16 ..  23
    can, em,  sub, esc, fsp, gsp, rsp, usp,  --  24 ..  31

    ' ', '!', '"', '#', '$', '%', '&', ''',  --  32 ..  39
    '(', ')', '*', '+', ',', '-', '.', '/',  --  40 ..  47
    '0', '1', '2', '3', '4', '5', '6', '7',  --  48 ..  55
    '8', '9', ':', ';', '<', '=', '>', '?',  --  56 ..  63
    '@', 'A', 'B', 'C', 'D', 'E', 'F', 'G',  --  64 ..  71
    'H', 'I', 'J', 'K', 'L', 'M', 'N', 'O',  --  72 ..  79
    'P', 'Q', 'R', 'S', 'T', 'U', 'V', 'W',  --  80 ..  87
    'X', 'Y', 'Z', '[', '\', ']', '^', '_',  --  88 ..  95
    '`', 'a', 'b', 'c', 'd', 'e', 'f', 'g',  --  96 .. 103
    'h', 'i', 'j', 'k', 'l', 'm', 'n', 'o',  -- 104 .. 111
    'p', 'q', 'r', 's', 't', 'u', 'v', 'w',  -- 112 .. 119
    'x', 'y', 'z', '{', '|', '}', '~', del,  -- 120 .. 127

    c128, c129, c130, c131, c132, c133, c134, c135,  -- 128 .. 135
    c136, c137, c138, c139, c140, c141, c142, c143,  -- 136 .. 143
    c144, c145, c146, c147, c148, c149, c150, c151,  -- 144 .. 151
    c152, c153, c154, c155, c156, c157, c158, c159,  -- 152 .. 159

    ' ', '¡', '¢', '£', '¤', '¥', '¦', '§',  -- 160 .. 167  (160 is no-break space)
    '¨', '©', 'ª', '«', '¬', '­', '®', '¯',  -- 168 .. 175  (173 is soft hyphen)
    '°', '±', '²', '³', '´', 'µ', '¶', '·',  -- 176 .. 183
    '¸', '¹', 'º', '»', '¼', '½', '¾', '¿',  -- 184 .. 191
    'À', 'Á', 'Â', 'Ã', 'Ä', 'Å', 'Æ', 'Ç',  -- 192 .. 199
    'È', 'É', 'Ê', 'Ë', 'Ì', 'Í', 'Î', 'Ï',  -- 200 .. 207
    'Ð', 'Ñ', 'Ò', 'Ó', 'Ô', 'Õ', 'Ö', '×',  -- 208 .. 215
    'Ø', 'Ù', 'Ú', 'Û', 'Ü', 'Ý', 'Þ', 'ß',  -- 216 .. 223
    'à', 'á', 'â', 'ã', 'ä', 'å', 'æ', 'ç',  -- 224 .. 231
    'è', 'é', 'ê', 'ë', 'ì', 'í', 'î', 'ï',  -- 232 .. 239
    'ð', 'ñ', 'ò', 'ó', 'ô', 'õ', 'ö', '÷',  -- 240 .. 247
    'ø', 'ù', 'ú', 'û', 'ü', 'ý', 'þ', 'ÿ'   -- 248 .. 255
  );

  type severity_level is (note, warning, error, failure);

  -- type universal_integer is range implementation_defined;  (anonymous, 64-bit in vams)
  -- type universal_real is range implementation_defined;     (anonymous, IEEE double in vams)

  type integer is range -2147483648 to 2147483647;

  type real is range -1.0e308 to 1.0e308;

  -- TIME counts femtoseconds in a 64-bit integer.
  type time is range -9223372036854775807 to 9223372036854775807
    units
      fs;                -- femtosecond
      ps  = 1000 fs;     -- picosecond
      ns  = 1000 ps;     -- nanosecond
      us  = 1000 ns;     -- microsecond
      ms  = 1000 us;     -- millisecond
      sec = 1000 ms;     -- second
      min = 60 sec;      -- minute
      hr  = 60 min;      -- hour
    end units;

  subtype delay_length is time range 0 fs to time'high;

  -- 1076.1: the analog solution domain, set by the simulator: QUIESCENT_DOMAIN
  -- during the initial operating-point (DC) computation, TIME_DOMAIN during
  -- transient simulation, FREQUENCY_DOMAIN during small-signal (AC/noise) analysis.
  type domain_type is (quiescent_domain, time_domain, frequency_domain);

  signal domain : domain_type := quiescent_domain;

  -- Current simulation time, as a TIME (digital kernel) ...
  impure function now return delay_length;

  -- ... and as a REAL number of seconds (analog solver, 1076.1).
  impure function now return real;

  -- 1076.1: the current frequency, in hertz, during frequency-domain analysis.
  impure function frequency return real;

  subtype natural is integer range 0 to integer'high;

  subtype positive is integer range 1 to integer'high;

  type string is array (positive range <>) of character;

  type boolean_vector is array (natural range <>) of boolean;

  type bit_vector is array (natural range <>) of bit;

  type integer_vector is array (natural range <>) of integer;

  -- 1076.1: the element type of the vector-valued quantities of the discipline packages.
  type real_vector is array (natural range <>) of real;

  type file_open_kind is (read_mode, write_mode, append_mode);

  type file_open_status is (open_ok, status_error, name_error, mode_error);

  attribute foreign : string;

end package standard;
