// The lock-free newest-value exchange between the physics thread and the haptic loop.
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>

#include "haptics/latest_value.hpp"

namespace imasim::haptics {
namespace {

TEST(LatestValue, NothingUntilPublishedThenTheNewest) {
  LatestValue<int> v;
  int out = -1;
  EXPECT_FALSE(v.read(out));
  v.publish(1);
  v.publish(2);
  v.publish(3);
  ASSERT_TRUE(v.read(out));
  EXPECT_EQ(out, 3);
  ASSERT_TRUE(v.read(out));  // nothing new: the same value again
  EXPECT_EQ(out, 3);
  v.publish(4);
  ASSERT_TRUE(v.read(out));
  EXPECT_EQ(out, 4);
}

// A value whose parts must agree: a torn read (half of one publish, half of another) breaks it.
struct Pair {
  std::uint64_t a = 0, b = 0;
  std::uint64_t filler[14] = {};
};

TEST(LatestValue, AReaderOnAnotherThreadNeverSeesATornOrOlderValue) {
  LatestValue<Pair> v;
  constexpr std::uint64_t kCount = 200000;
  std::thread producer([&] {
    for (std::uint64_t k = 1; k <= kCount; ++k) {
      Pair p;
      p.a = k;
      p.b = ~k;
      for (auto& f : p.filler)
        f = k;
      v.publish(p);
    }
  });
  std::uint64_t last = 0, reads = 0;
  Pair p;
  while (last < kCount) {
    if (!v.read(p)) continue;
    ++reads;
    ASSERT_EQ(p.b, ~p.a);
    for (const auto f : p.filler)
      ASSERT_EQ(f, p.a);
    ASSERT_GE(p.a, last);  // never older than what was read before
    last = p.a;
  }
  producer.join();
  EXPECT_EQ(last, kCount);
  EXPECT_GT(reads, 0u);
}

}  // namespace
}  // namespace imasim::haptics
