-- top: tb_trackin
entity tb_tracking is end;
architecture a of tb_tracking is
begin
end;
