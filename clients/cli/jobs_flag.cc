#include "clients/cli/jobs_flag.h"

#include <algorithm>
#include <string>
#include <thread>

namespace gc::cli {

FlagSpec jobs_flag() {
  return {"jobs", "N", "worker threads, 1..256",
          std::to_string(std::max(1u, std::thread::hardware_concurrency())), false, 'j',
          {"threads"}};
}

int jobs_from(const Flags& flags) { return flags.integer("jobs", 1, 256); }

}  // namespace gc::cli
