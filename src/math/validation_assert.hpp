#pragma once
// IMASIM_ASSERT(condition): an invariant check compiled in by the validation build
// (-DIMASIM_VALIDATION=ON, which `make test` runs under ASan+UBSan), not by NDEBUG, so the
// Release tests and a user's build pay nothing and CI still checks every invariant (as Box2D's
// B2_ENABLE_ASSERT). A failure names the condition, file and line, then aborts.
#include <cstdio>
#include <cstdlib>

namespace imasim {

[[noreturn]] inline void validation_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: invariant failed: %s\n", file, line, condition);
  std::abort();
}

}  // namespace imasim

#if IMASIM_VALIDATION
#define IMASIM_ASSERT(condition) \
  ((condition) ? void(0) : ::imasim::validation_failed(#condition, __FILE__, __LINE__))
#else
#define IMASIM_ASSERT(condition) ((void)0)
#endif
