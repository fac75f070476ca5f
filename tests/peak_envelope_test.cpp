// The force plots' thinned history (ui/peak_envelope.hpp): each point the largest of its group,
// so a one-sample peak anywhere in a group survives, in order, oldest first.
#include <gtest/gtest.h>

#include "ui/peak_envelope.hpp"

namespace imasim::ui {
namespace {

TEST(PeakEnvelope, EachPointIsTheLargestOfItsGroupSoAPeakSurvives) {
  std::array<float, 240> history{};
  for (std::size_t i = 0; i < history.size(); ++i)
    history[i] = 0.01f * float(i);  // rising: each group's last sample
  history[5] = 4.5f;                // a one-sample peak inside group 1
  history[239] = -1.0f;             // the newest sample is low: its group keeps 2.38
  const auto peaks = peak_envelope<4>(history);
  ASSERT_EQ(peaks.size(), 60u);
  EXPECT_FLOAT_EQ(peaks[0], 0.03f);
  EXPECT_FLOAT_EQ(peaks[1], 4.5f);
  EXPECT_FLOAT_EQ(peaks[2], 0.11f);
  EXPECT_FLOAT_EQ(peaks[59], 2.38f);
}

}  // namespace
}  // namespace imasim::ui
