// Samples of IDL C types with owners: one built for writing (its strings and sequences freed by
// dds_sample_free) and a batch taken on loan from a reader (returned with dds_return_loan).
#pragma once

#include <dds/dds.h>

#include <array>
#include <cstring>

#include "protocol/dds_entity.h"

namespace gc::protocol {

/// A zeroed sample of C type T whose contents (dds_alloc'ed strings, sequences, optionals) are
/// released with dds_sample_free(DDS_FREE_CONTENTS) on destruction.
template <typename T>
class OwnedSample {
 public:
  explicit OwnedSample(const dds_topic_descriptor_t& type) : type_(&type) {
    std::memset(&sample_, 0, sizeof(sample_));
  }
  OwnedSample(const OwnedSample&) = delete;
  OwnedSample& operator=(const OwnedSample&) = delete;
  ~OwnedSample() { dds_sample_free(&sample_, type_, DDS_FREE_CONTENTS); }

  T& get() noexcept { return sample_; }
  const T& get() const noexcept { return sample_; }

 private:
  const dds_topic_descriptor_t* type_;
  T sample_;
};

/// Up to kMax samples taken on loan from `reader` (dds_take with a null buffer), returned to the
/// reader when this object goes.
template <typename T, std::size_t kMax = 64>
class LoanedSamples {
 public:
  explicit LoanedSamples(dds_entity_t reader) : reader_(reader) {
    buffers_.fill(nullptr);
    const dds_return_t n = dds_take(reader_, buffers_.data(), infos_.data(), kMax, kMax);
    count_ = n > 0 ? static_cast<std::size_t>(n) : 0;
  }
  LoanedSamples(const LoanedSamples&) = delete;
  LoanedSamples& operator=(const LoanedSamples&) = delete;
  ~LoanedSamples() {
    if (count_ > 0) dds_return_loan(reader_, buffers_.data(), static_cast<int32_t>(count_));
  }

  std::size_t size() const noexcept { return count_; }
  const dds_sample_info_t& info(std::size_t i) const noexcept { return infos_[i]; }
  /// Sample i; meaningful only when info(i).valid_data.
  const T& operator[](std::size_t i) const noexcept { return *static_cast<const T*>(buffers_[i]); }

 private:
  dds_entity_t reader_;
  std::array<void*, kMax> buffers_;
  std::array<dds_sample_info_t, kMax> infos_;
  std::size_t count_ = 0;
};

}  // namespace gc::protocol
