// Issue 40: a client built from the IDL alone (foreign_batch_client.c: plain C, Cyclone's C API,
// the idlc types, none of our C++) sends a batch with bad cases between good ones to a
// gearcoupling-service on this test's own domain, over loopback, and finds each case's status
// and field in place, as docs/protocol.md "Batches" names them. The checks are the client's:
// its exit status says whether they held, its standard error which did not.
#include <string>

#include <gtest/gtest.h>

#include "tests/service/service_process.h"

namespace gc {
namespace {

TEST(ForeignClient, ABatchFromTheIdlAloneGetsEachCasesErrorInPlace) {
  test::ServiceProcess service;
  test::ChildProcess client({GC_FOREIGN_BATCH_CLIENT_BINARY, std::to_string(test::test_domain())});
  // 0: every case answered as expected; 1: a check failed; 2: no instance or no reply in 20 s.
  EXPECT_EQ(client.wait_exit(60.0), 0);
}

}  // namespace
}  // namespace gc
