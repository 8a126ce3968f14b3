-- Two packages that use each other: neither can be analysed first.
use work.second.all;
package first is
  constant a : integer := 1;
end package first;

use work.first.all;
package second is
  constant b : integer := a + 1;
end package second;
