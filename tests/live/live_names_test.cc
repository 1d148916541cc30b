// The operator partition (live/live_names.h): what a swap writer of operator-NAME adds, and what
// the monitor reads back from a writer's partitions for its audit trail.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/model_error.h"
#include "live/live_names.h"

namespace gc::live {
namespace {

TEST(OperatorPartition, IsNamedAfterTheOperatorAndReadBackAsItsIdentity) {
  EXPECT_EQ(operator_partition("shift-2"), "gearcoupling.live.operator.shift-2");
  EXPECT_EQ(operator_identity_of({"gearcoupling.live.cell.dyno1", "gearcoupling.live.operator.shift-2"}),
            "operator-shift-2");
  EXPECT_EQ(operator_identity_of({"gearcoupling.live.cell.dyno1"}), "");
  EXPECT_EQ(operator_identity_of({"gearcoupling.live.operator."}), "");
}

// The names make-security.sh gives identities: 1 to 32 of a-z 0-9 _ -, a letter or digit first.
TEST(OperatorPartition, RefusesANameNoIdentityCanHaveNamingTheField) {
  for (const char* bad : {"", "Shift", "-x", "a*", "a.b", "012345678901234567890123456789012"}) {
    try {
      operator_partition(bad);
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.field(), "operator") << bad;
    }
  }
}

TEST(OperatorPartition, TheProcessOperatorIsItsOperatorIdentitysName) {
  ::setenv("GC_IDENTITY", "operator-shift", 1);
  EXPECT_EQ(operator_of_identity(), "shift");
  ::setenv("GC_IDENTITY", "dashboard-main", 1);
  EXPECT_EQ(operator_of_identity(), "");
  ::unsetenv("GC_IDENTITY");
  EXPECT_EQ(operator_of_identity(), "");
}

}  // namespace
}  // namespace gc::live
