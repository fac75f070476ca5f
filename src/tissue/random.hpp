#pragma once
// SplitMix64: a small, fast generator whose sequence is fixed by its seed on every platform
// (the standard distributions are not), so generated anatomy is reproducible everywhere.
#include <cstdint>

#include "math/types.hpp"

namespace imasim::tissue {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1), 53 random bits.
  Real uniform() { return Real(double(next() >> 11) * 0x1.0p-53); }

 private:
  std::uint64_t state_;
};

}  // namespace imasim::tissue
