// The lock-free newest-value exchange between threads (base/latest_value.hpp), both ways of using
// it: by value (the physics thread to the haptic loop), where a reader never sees a torn or older
// value; and in place (the frame to the drawing thread), where the reader gets the newest
// published value whole, never one being filled, and knows whether it is new.
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <vector>

#include "base/latest_value.hpp"

namespace imasim::base {
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

TEST(LatestValue, InPlaceReadsTheNewestPublishedValueAndSaysWhetherItIsNew) {
  LatestValue<std::vector<int>> b;
  EXPECT_EQ(b.latest(), nullptr);
  b.back().assign(3, 1);
  b.publish();
  b.back().assign(3, 2);
  b.publish();
  bool fresh = false;
  const std::vector<int>* v = b.latest(&fresh);
  ASSERT_NE(v, nullptr);
  EXPECT_TRUE(fresh);
  EXPECT_EQ(*v, std::vector<int>(3, 2));
  b.back().assign(3, 7);  // being filled: not seen
  EXPECT_EQ(b.latest(&fresh), v);
  EXPECT_FALSE(fresh);
  EXPECT_EQ(*v, std::vector<int>(3, 2));
}

TEST(LatestValue, InPlaceAcrossThreadsEveryReadIsWholeAndInOrder) {
  LatestValue<std::vector<int>> b;
  constexpr int kValues = 20000;
  std::thread producer([&] {
    for (int k = 1; k <= kValues; ++k) {
      b.back().assign(64, k);
      b.publish();
    }
  });
  int last = 0;
  while (last < kValues) {
    const std::vector<int>* v = b.latest();
    if (!v) continue;
    ASSERT_EQ(v->size(), 64u);
    for (int x : *v)
      ASSERT_EQ(x, v->front()) << "a torn frame";
    ASSERT_GE(v->front(), last);
    last = v->front();
  }
  producer.join();
}

}  // namespace
}  // namespace imasim::base
