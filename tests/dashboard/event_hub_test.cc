// The dashboard's fan-out: each browser's queue is bounded and drops its oldest update, so a
// slow browser neither grows memory nor holds up the others.
#include "clients/dashboard/event_hub.h"

#include <gtest/gtest.h>

namespace gc::dashboard {
namespace {

using std::chrono::milliseconds;

TEST(EventHub, EverySubscriberGetsEveryUpdateInOrder) {
  EventHub hub(4);
  auto first = hub.subscribe();
  auto second = hub.subscribe();
  hub.publish("a");
  hub.publish("b");
  for (const auto& queue : {first, second}) {
    EXPECT_EQ(*queue->pop(milliseconds(0)), "a");
    EXPECT_EQ(*queue->pop(milliseconds(0)), "b");
    EXPECT_EQ(queue->pop(milliseconds(0)), nullptr);
  }
}

TEST(EventHub, ASlowSubscriberLosesItsOldestUpdatesOnlyAndTheOthersLoseNothing) {
  EventHub hub(3);
  auto slow = hub.subscribe();
  auto fast = hub.subscribe();
  for (int k = 0; k < 10; ++k) {
    hub.publish(std::to_string(k));
    EXPECT_EQ(*fast->pop(milliseconds(0)), std::to_string(k));
  }
  EXPECT_EQ(*slow->pop(milliseconds(0)), "7");  // 0..6 dropped: the queue holds 3
  EXPECT_EQ(*slow->pop(milliseconds(0)), "8");
  EXPECT_EQ(*slow->pop(milliseconds(0)), "9");
  EXPECT_EQ(slow->dropped(), 7u);
  EXPECT_EQ(fast->dropped(), 0u);
  EXPECT_EQ(hub.dropped(), 7u);
}

TEST(EventHub, ClosingWakesAWaitingReaderAndEndsItsStream) {
  EventHub hub(2);
  auto queue = hub.subscribe();
  hub.close();
  EXPECT_EQ(queue->pop(milliseconds(10000)), nullptr);  // returns at once, not after 10 s
  EXPECT_TRUE(queue->closed());
  EXPECT_TRUE(hub.subscribe()->closed());
}

TEST(EventHub, AnUnsubscribedQueueGetsNothingAndItsDropsStayCounted) {
  EventHub hub(1);
  auto queue = hub.subscribe();
  hub.publish("a");
  hub.publish("b");  // drops "a"
  hub.unsubscribe(queue);
  hub.publish("c");
  EXPECT_EQ(*queue->pop(milliseconds(0)), "b");
  EXPECT_EQ(queue->pop(milliseconds(0)), nullptr);
  EXPECT_EQ(hub.subscribers(), 0u);
  EXPECT_EQ(hub.dropped(), 1u);
}

}  // namespace
}  // namespace gc::dashboard
