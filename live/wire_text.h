// Strings into the IDL's C types, shared by the monitor's writers (health, proposals, its status).
#pragma once

#include <algorithm>
#include <string>

namespace gc::live {

/// `text` lent to a sample being written (not copied: the sample must not outlive it).
inline char* lend(const std::string& text) { return const_cast<char*>(text.c_str()); }

/// `test_cell` into a string<64> key, cut at 64 characters (names are checked before).
inline void set_test_cell(char (&out)[65], const std::string& test_cell) {
  const std::size_t n = std::min<std::size_t>(test_cell.size(), 64);
  std::copy_n(test_cell.c_str(), n, out);
  out[n] = '\0';
}

}  // namespace gc::live
