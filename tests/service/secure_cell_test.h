// The fixture of the tests that run on a SecureCell: made in SetUp, or the test skipped with the
// reason where Cyclone's DDS Security plugins are not installed.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/service/secure_cell.h"

namespace gc::test {

class SecureCellTest : public testing::Test {
 protected:
  /// Makes cell_ with the script's `more_args` (SecureCell), or skips the test (then IsSkipped()).
  void make_cell(const std::string& more_args = {}) {
    if (!security_plugins_installed()) {
      GTEST_SKIP() << "Cyclone DDS Security plugins (libdds_security_{auth,ac,crypto}.so in "
                      "/usr/lib/x86_64-linux-gnu/libddsc0debian) are not installed";
    }
    cell_ = std::make_unique<SecureCell>(more_args);
  }
  std::unique_ptr<SecureCell> cell_;
};

}  // namespace gc::test
