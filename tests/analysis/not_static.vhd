-- Where the LRM asks for a static expression, a name whose value only the simulation knows.
entity counter is
  generic (width : natural := 4);
  port (clk : in bit);
end entity counter;

architecture rtl of counter is
  signal top_lane : integer := 9;
  signal count : integer := 0;
  constant reset_value : integer := 0;
begin
  step : process (clk)
    variable last : integer := 3;
  begin
    case count is
      when reset_value => count <= 1;        -- a constant: fine
      when last => count <= 0;               -- a variable: not locally static
      when others => count <= count + 1;
    end case;
  end process step;

  lanes : for i in 0 to top_lane generate      -- a signal bound: not globally static
  end generate lanes;

  wide : for i in 0 to width - 1 generate    -- a generic bound: fine
  end generate wide;
end architecture rtl;
