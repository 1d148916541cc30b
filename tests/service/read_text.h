// A whole text file (a service's log) as one string; "" when it cannot be read.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace gc::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace gc::test
