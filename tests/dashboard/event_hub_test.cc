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

TEST(EventHub, RefusesASubscriberBeyondItsMostAndCountsIt) {
  EventHub hub(4, 2);
  auto first = hub.subscribe();
  auto second = hub.subscribe();
  EXPECT_EQ(hub.subscribe(), nullptr);
  EXPECT_EQ(hub.refused(), 1u);
  EXPECT_EQ(hub.subscribers(), 2u);
  hub.unsubscribe(first);  // a browser left: its place is free
  EXPECT_NE(hub.subscribe(), nullptr);
}

TEST(EventHub, AQueueHoldsAtMostItsBytesAndAlwaysTheNewest) {
  EventHub hub(16, 1, 1000);
  auto slow = hub.subscribe();
  for (char c : std::string("abcdefgh")) hub.publish(std::string(300, c));
  // 1000 bytes hold three updates of 300: the five oldest went, counted.
  EXPECT_EQ(*slow->pop(milliseconds(0)), std::string(300, 'f'));
  EXPECT_EQ(*slow->pop(milliseconds(0)), std::string(300, 'g'));
  EXPECT_EQ(*slow->pop(milliseconds(0)), std::string(300, 'h'));
  EXPECT_EQ(slow->dropped(), 5u);
  hub.publish(std::string(5000, 'x'));  // larger than the bound alone: kept, as the latest state
  EXPECT_EQ(slow->pop(milliseconds(0))->size(), 5000u);
}

}  // namespace
}  // namespace gc::dashboard
