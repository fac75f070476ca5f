#pragma once
// Property checks inside fuzz targets: a broken property aborts, which libFuzzer reports as a
// crash and saves the input that broke it.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace imasim::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz property broken: %s\n", what.c_str());
  std::abort();
}

inline void require(bool holds, const std::string& what) {
  if (!holds) fail(what);
}

}  // namespace imasim::fuzz
