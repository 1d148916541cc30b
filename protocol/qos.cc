#include "protocol/qos.h"

namespace gc::protocol {
namespace {

dds_duration_t seconds(double s) { return static_cast<dds_duration_t>(s * 1e9); }

}  // namespace

Qos request_reply_qos(double max_blocking_s) {
  Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(max_blocking_s));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  return qos;
}

std::int32_t reply_history_depth(Calculation calculation) {
  switch (calculation) {
    case Calculation::kToothContact: return 64;
    case Calculation::kBatch: return kBatchReplyHistoryDepth;
    default: return 512;
  }
}

Qos tagged_reply_writer_qos(const std::string& tag, Calculation calculation, double max_blocking_s) {
  Qos qos = request_reply_qos(max_blocking_s);
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, reply_history_depth(calculation));
  dds_qset_userdata(qos.get(), tag.data(), tag.size());
  return qos;
}

Qos status_qos(double lease_s) {
  Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(1.0));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, seconds(lease_s));
  return qos;
}

Qos status_reader_qos() {
  Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(1.0));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  return qos;
}

Qos partition_qos(const std::string& partition) {
  Qos qos;
  dds_qset_partition1(qos.get(), partition.c_str());
  return qos;
}

}  // namespace gc::protocol
