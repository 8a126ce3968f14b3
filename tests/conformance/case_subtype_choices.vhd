-- A subtype name as a case choice stands for its range (Ashenden's instruction decoder);
-- 'base of a subtype.
-- vams: stop 1 ns

entity tb_case_subtype_choices is
end entity tb_case_subtype_choices;

architecture test of tb_case_subtype_choices is
  type opcodes is (nop, add, subtract, load, store, jump, jumpsub, branch, halt);
  subtype control_transfer_opcodes is opcodes range jump to branch;
  subtype digit is integer range 0 to 9;
begin
  process is
    variable kind : string(1 to 7);
    variable class : natural;
  begin
    -- 'base: the subtype's base type, its whole range.
    assert control_transfer_opcodes'left = jump and control_transfer_opcodes'base'left = nop;
    assert digit'high = 9 and digit'base'high = integer'high;
    for op in opcodes loop
      case op is
        when load | add | subtract => kind := "operate";
        when control_transfer_opcodes | store => kind := "address";
        when others => kind := "nothing";
      end case;
      case op is
        when jump => assert kind = "address";
        when branch => assert kind = "address";
        when store => assert kind = "address";
        when add => assert kind = "operate";
        when halt => assert kind = "nothing";
        when others => null;
      end case;
    end loop;
    for n in 0 to 20 loop
      case n is
        when digit => class := 1;
        when others => class := 2;
      end case;
      assert (n <= 9 and class = 1) or (n > 9 and class = 2);
    end loop;
    wait;
  end process;
end architecture test;
