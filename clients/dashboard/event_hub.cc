#include "clients/dashboard/event_hub.h"

namespace gc::dashboard {

void EventQueue::push(const std::shared_ptr<const std::string>& event) {
  {
    std::lock_guard lock(mutex_);
    if (closed_) return;
    while (!events_.empty() &&
           (events_.size() >= capacity_ || bytes_ + event->size() > max_bytes_)) {
      bytes_ -= events_.front()->size();
      events_.pop_front();
      dropped_ += 1;
    }
    events_.push_back(event);
    bytes_ += event->size();
  }
  ready_.notify_one();
}

std::shared_ptr<const std::string> EventQueue::pop(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, timeout, [this] { return closed_ || !events_.empty(); });
  if (closed_ || events_.empty()) return nullptr;
  auto event = std::move(events_.front());
  events_.pop_front();
  bytes_ -= event->size();
  return event;
}

void EventQueue::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  ready_.notify_all();
}

bool EventQueue::closed() const {
  std::lock_guard lock(mutex_);
  return closed_;
}

std::uint64_t EventQueue::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

std::shared_ptr<EventQueue> EventHub::subscribe() {
  auto queue = std::make_shared<EventQueue>(queue_capacity_, queue_bytes_);
  std::lock_guard lock(mutex_);
  if (!closed_ && queues_.size() >= max_subscribers_) {
    refused_ += 1;
    return nullptr;
  }
  if (closed_) {
    queue->close();
  } else {
    queues_.insert(queue);
  }
  return queue;
}

void EventHub::unsubscribe(const std::shared_ptr<EventQueue>& queue) {
  std::lock_guard lock(mutex_);
  if (queues_.erase(queue) > 0) dropped_by_gone_ += queue->dropped();
}

void EventHub::publish(std::string event) {
  const auto shared = std::make_shared<const std::string>(std::move(event));
  std::lock_guard lock(mutex_);
  for (const auto& queue : queues_) queue->push(shared);
}

void EventHub::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  for (const auto& queue : queues_) queue->close();
}

std::size_t EventHub::subscribers() const {
  std::lock_guard lock(mutex_);
  return queues_.size();
}

std::uint64_t EventHub::dropped() const {
  std::lock_guard lock(mutex_);
  std::uint64_t total = dropped_by_gone_;
  for (const auto& queue : queues_) total += queue->dropped();
  return total;
}

std::uint64_t EventHub::refused() const {
  std::lock_guard lock(mutex_);
  return refused_;
}

}  // namespace gc::dashboard
