// Who the audit trail names for a swap (live/swap_operator.h, issue 39): a person, from
// --operator or from the operator identity, never the process's USER@HOST.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/model_error.h"
#include "live/swap_operator.h"

namespace gc::live {
namespace {

TEST(SwapOperator, IsTheNameGivenWithOperatorEvenUnderAnOperatorIdentity) {
  EXPECT_EQ(swap_operator("Ada Lovelace", ""), "Ada Lovelace");
  EXPECT_EQ(swap_operator("ada", "shift-2"), "ada");   // the identity is audited apart
}

TEST(SwapOperator, IsTheOperatorIdentitysSubjectNameWithoutOperator) {
  EXPECT_EQ(swap_operator("", "shift-2"), "operator-shift-2");
}

TEST(SwapOperator, IsRequiredWithoutAnOperatorIdentityNamingTheFlag) {
  try {
    swap_operator("", "");
    ADD_FAILURE() << "no operator accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "--operator");
    EXPECT_NE(std::string(error.what()).find("--operator: required"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("GC_IDENTITY=operator-NAME"), std::string::npos)
        << error.what();
  }
}

// ';' and '=' would split the writer's USER_DATA "by=...;source=..."; the trail keeps 128 bytes.
TEST(SwapOperator, RefusesANameTheTrailCannotHoldNamingTheValueAndTheRange) {
  for (const std::string& bad : std::vector<std::string>{"a;source=forged", "a=b", "tab\there", "   ", std::string(65, 'x')}) {
    try {
      swap_operator(bad, "shift");
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.field(), "--operator") << bad;
      EXPECT_NE(std::string(error.what()).find("allowed 1 to 64 printable characters"),
                std::string::npos) << error.what();
    }
  }
  EXPECT_EQ(swap_operator(std::string(64, 'x'), ""), std::string(64, 'x'));
}

TEST(SwapOperator, UserDataIsWhatTheMonitorReadsBack) {
  EXPECT_EQ(swap_user_data("Ada Lovelace", "proposal 0123456789abcdef"),
            "by=Ada Lovelace;source=proposal 0123456789abcdef");
}

}  // namespace
}  // namespace gc::live
