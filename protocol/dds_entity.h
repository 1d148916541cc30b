// Small RAII owners for the Cyclone DDS C API: an entity handle deleted with its owner, a QoS
// object, and the error type every failed call becomes.
#pragma once

#include <dds/dds.h>

#include "protocol/dds_config.h"
#include "protocol/dds_error.h"

#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <string>
#include <utility>

namespace gc::protocol {

static_assert(std::is_same_v<dds_return_t, std::int32_t>, "DdsError's code is a dds_return_t");

/// Returns `result` (an entity or a count) when it is not negative, else throws DdsError.
dds_entity_t check_dds(dds_entity_t result, const char* call);

/// Owns one DDS entity: dds_delete() on destruction (which also deletes its children).
class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  Entity(const Entity&) = delete;
  Entity& operator=(const Entity&) = delete;
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    if (this != &other) {
      reset();
      handle_ = std::exchange(other.handle_, 0);
    }
    return *this;
  }
  ~Entity() { reset(); }

  dds_entity_t get() const noexcept { return handle_; }
  explicit operator bool() const noexcept { return handle_ > 0; }
  void reset() noexcept {
    if (handle_ > 0) dds_delete(handle_);
    handle_ = 0;
  }

 private:
  dds_entity_t handle_ = 0;
};

/// Owns a dds_qos_t.
class Qos {
 public:
  Qos() : qos_(dds_create_qos()) {}
  Qos(const Qos&) = delete;
  Qos& operator=(const Qos&) = delete;
  Qos(Qos&& other) noexcept : qos_(std::exchange(other.qos_, nullptr)) {}
  Qos& operator=(Qos&&) = delete;
  ~Qos() {
    if (qos_ != nullptr) dds_delete_qos(qos_);
  }
  dds_qos_t* get() const noexcept { return qos_; }

 private:
  dds_qos_t* qos_;
};

/// A participant on `domain` with `config` (protocol/dds_config.h). Cyclone reads
/// CYCLONEDDS_URI itself, so the environment's and the default configuration need nothing; the
/// installed one is given to dds_create_domain(), whose domain then lives as long as the process
/// (later participants on `domain` join it). Throws DdsError.
dds_entity_t create_participant(int domain, const DdsConfig& config);

}  // namespace gc::protocol
