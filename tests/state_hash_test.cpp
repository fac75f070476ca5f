#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "math/state_hash.hpp"

namespace imasim {
namespace {

TEST(StateHash, MatchesTheFnv1aReferenceValues) {
  // Published FNV-1a 64-bit test vectors.
  EXPECT_EQ(hash_bytes("", 0), 0xcbf29ce484222325ull);
  EXPECT_EQ(hash_bytes("a", 1), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(hash_bytes("foobar", 6), 0x85944171f73967e8ull);
}

TEST(StateHash, ChangesWithASingleBit) {
  double a[2] = {1.0, 2.0};
  const auto h0 = hash_span(std::span<const double>(a));
  a[1] = std::nextafter(2.0, 3.0);
  EXPECT_NE(h0, hash_span(std::span<const double>(a)));
}

TEST(StateHash, PrintsSixteenHexDigits) {
  EXPECT_EQ(to_hex(0), "0000000000000000");
  EXPECT_EQ(to_hex(0xaf63dc4c8601ec8cull), "af63dc4c8601ec8c");
}

}  // namespace
}  // namespace imasim
