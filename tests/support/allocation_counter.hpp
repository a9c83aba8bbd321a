#pragma once
// Counts every global allocation of the test binary that links cyber_allocation_counter (an
// object library: it replaces operator new/delete, so only tests that prove "no allocation" link
// it). Compare the count before and after the code under test.

namespace cyber::test {

long allocationCount();

}  // namespace cyber::test
