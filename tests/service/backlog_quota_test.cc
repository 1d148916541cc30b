// The reply backlog's limits (service/backlog_quota.h): a client that does not read fills only
// its own share.
#include <gtest/gtest.h>

#include "service/backlog_quota.h"

namespace gc::service {
namespace {

TEST(BacklogQuota, OneClientFillsOnlyItsShare) {
  BacklogQuota quota(10, 4);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(quota.take(1));
  EXPECT_FALSE(quota.take(1));  // client 1's share is full
  EXPECT_TRUE(quota.take(2));   // another client still finds room
  EXPECT_EQ(quota.of(1), 4u);
  EXPECT_EQ(quota.of(2), 1u);
  EXPECT_EQ(quota.total(), 5u);
  quota.give_back(1);
  EXPECT_TRUE(quota.take(1));
}

TEST(BacklogQuota, TheTotalBoundsAllClients) {
  BacklogQuota quota(6, 4);
  for (std::uint64_t client = 1; client <= 3; ++client) {
    EXPECT_TRUE(quota.take(client));
    EXPECT_TRUE(quota.take(client));
  }
  EXPECT_FALSE(quota.take(4));
  EXPECT_EQ(quota.of(4), 0u);  // a refused take counts nothing
  quota.give_back(2);
  quota.give_back(2);
  EXPECT_EQ(quota.of(2), 0u);
  EXPECT_EQ(quota.total(), 4u);
  EXPECT_TRUE(quota.take(4));
}

TEST(BacklogQuota, GivingBackForAnUnknownClientChangesNothing) {
  BacklogQuota quota(2, 2);
  quota.give_back(7);
  EXPECT_EQ(quota.total(), 0u);
  EXPECT_TRUE(quota.take(7));
  EXPECT_TRUE(quota.take(7));
  EXPECT_FALSE(quota.take(8));
}

}  // namespace
}  // namespace gc::service
