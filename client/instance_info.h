// A status sample (gearcoupling/status, docs/protocol.md) as the client library's InstanceInfo
// (client_types.h): what the client, `gearcoupling status`, the dashboard and /metrics read. Not
// installed: it names idlc's generated type.
#pragma once

#include "client/client_types.h"
#include "gearcoupling.h"

namespace gc::client {

/// The InstanceInfo a status sample carries. Catalogue definitions the protocol refuses (a name
/// over its bound) are left out of `definitions`, but their names stay in `catalogue`.
InstanceInfo instance_info_from_wire(const gearcoupling_ServiceStatus& status);

}  // namespace gc::client
