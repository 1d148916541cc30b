// Every QoS of the live test-cell topics, in one place (docs/protocol.md explains each choice).
#pragma once

#include "protocol/dds_entity.h"

namespace gc::live {

/// Measurement writers (a DAQ, replay): RELIABLE, KEEP_ALL, VOLATILE, liveliness AUTOMATIC
/// 2 s. A reader that must lose nothing (the monitor, record) gets every sample; the writer
/// blocks at most `max_blocking_s` when such a reader falls behind.
protocol::Qos measurement_writer_qos(double max_blocking_s = 1.0);
/// Readers that must lose nothing (monitor, record): RELIABLE, KEEP_ALL.
protocol::Qos measurement_reader_qos();
/// Residual writers: RELIABLE, KEEP_LAST 64 per test cell: never blocks the monitor.
protocol::Qos residual_qos();
/// Health: RELIABLE, KEEP_LAST 1, TRANSIENT_LOCAL (late readers get every cell at once),
/// liveliness AUTOMATIC 3 s on the writer.
protocol::Qos health_writer_qos();
protocol::Qos health_reader_qos();
/// Model swaps: RELIABLE, KEEP_LAST 1 per test cell, TRANSIENT_LOCAL, so a monitor that
/// (re)starts gets each cell's latest model.
protocol::Qos model_qos();
/// Proposals and the monitor's status: as the health (RELIABLE, KEEP_LAST 1 per key,
/// TRANSIENT_LOCAL: a late reader gets every cell's proposal and the audit trail at once).
protocol::Qos proposal_qos();
protocol::Qos monitor_status_qos();

}  // namespace gc::live
