// The frame exchange (ui/triple_buffer.hpp): the reader gets the newest published value whole,
// in place, never one being filled, and knows whether it is new; across threads every value
// read is one that was published, in order.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "ui/triple_buffer.hpp"

namespace imasim::ui {
namespace {

TEST(TripleBuffer, ReadsTheNewestPublishedValue) {
  TripleBuffer<std::vector<int>> b;
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

TEST(TripleBuffer, AcrossThreadsEveryReadIsWholeAndInOrder) {
  TripleBuffer<std::vector<int>> b;
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
}  // namespace imasim::ui
