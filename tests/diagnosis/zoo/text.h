// printf-style formatting into a std::string, for the one-line descriptions of a draw.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace gc::zoo {

inline std::string format(const char* f, ...) {
  char buf[512];
  va_list args;
  va_start(args, f);
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  return buf;
}

}  // namespace gc::zoo
