// Every live test talks DDS over loopback only, on its own domain.
#include <gtest/gtest.h>

#include "tests/service/service_process.h"

int main(int argc, char** argv) {
  gc::test::use_loopback_config();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
