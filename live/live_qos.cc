#include "live/live_qos.h"

namespace gc::live {
namespace {

dds_duration_t seconds(double s) { return static_cast<dds_duration_t>(s * 1e9); }

}  // namespace

protocol::Qos measurement_writer_qos(double max_blocking_s) {
  protocol::Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(max_blocking_s));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, seconds(2.0));
  return qos;
}

protocol::Qos measurement_reader_qos() {
  protocol::Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(1.0));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  return qos;
}

protocol::Qos residual_qos() {
  protocol::Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(0.1));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 64);
  dds_qset_durability(qos.get(), DDS_DURABILITY_VOLATILE);
  return qos;
}

protocol::Qos health_reader_qos() {
  protocol::Qos qos;
  dds_qset_reliability(qos.get(), DDS_RELIABILITY_RELIABLE, seconds(1.0));
  dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, 1);
  dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  return qos;
}

protocol::Qos health_writer_qos() {
  protocol::Qos qos = health_reader_qos();
  dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, seconds(3.0));
  return qos;
}

protocol::Qos model_qos() { return health_reader_qos(); }
protocol::Qos proposal_qos() { return health_reader_qos(); }
protocol::Qos monitor_status_qos() { return health_reader_qos(); }

}  // namespace gc::live
