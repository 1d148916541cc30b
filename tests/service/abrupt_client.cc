// A client that dies mid-request: sends tooth-contact requests, then leaves with _exit() before
// any reply arrives, without deleting its DDS entities (as a crash would). Used by
// resilience_test.cc. usage: abrupt_client DOMAIN REQUESTS
#include <unistd.h>

#include <cstdlib>
#include <future>
#include <vector>

#include "client/client.h"
#include "tests/service/service_process.h"

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  gc::test::use_loopback_config();
  auto* client = new gc::client::Client({std::atoi(argv[1]), std::chrono::seconds(10)});
  if (!client->wait_for_service(gc::protocol::Calculation::kToothContact, std::chrono::seconds(10))) {
    return 3;
  }
  std::vector<std::future<gc::ToothContact>> futures;
  for (int r = 0; r < std::atoi(argv[2]); ++r) {
    futures.push_back(client->call_async<gc::protocol::Calculation::kToothContact>(
        {gc::protocol::CatalogueName{"nrel_downwind"}, {1.0e6 + r, 0.01, 0.0, 0.1}, {}}));
  }
  _exit(0);
}
