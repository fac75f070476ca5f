// A script played several times in a row (surgery/input_script_repeat.hpp).
#include <gtest/gtest.h>

#include "surgery/input_script_repeat.hpp"

namespace imasim::surgery {
namespace {

const char* kCycle =
    "0.0 right tool 0.01 0 0  0 0 0\n"
    "0.0 right pedal cut\n"
    "1.0 right pedal off\n"
    "2.0 right tool 0.03 0 0  0 0 0\n"
    "2.0 left jaw close\n";

TEST(InputScriptRepeat, EachCopyStartsOnePeriodAfterThePrevious) {
  const InputScript once = parse_input_script(kCycle, "cycle.script");
  const InputScript three = repeat_input_script(once, 3, 2.5);
  EXPECT_DOUBLE_EQ(three.end_time(), 2 * 2.5 + 2.0);
  ASSERT_EQ(three.right.poses.size(), 6u);
  EXPECT_DOUBLE_EQ(three.right.poses[4].time, 5.0);
  // The pedal: cut from 0, 2.5 and 5 s for one second each.
  EXPECT_EQ(sample_instrument(three.right, 2.6).pedal, PedalMode::cut);
  EXPECT_EQ(sample_instrument(three.right, 3.6).pedal, PedalMode::off);
  EXPECT_EQ(sample_instrument(three.right, 5.0).pedal, PedalMode::cut);
  // Between copies the pose moves from the last key (x = 0.03 at 2 s) to the first (0.01 at
  // 2.5 s): halfway at 2.25 s.
  EXPECT_NEAR(sample_instrument(three.right, 2.25).pose.translation.x(), 0.02, 1e-12);
  EXPECT_NEAR(sample_instrument(three.right, 7.0).pose.translation.x(), 0.03, 1e-12);
  EXPECT_EQ(sample_instrument(three.left, 4.6).jaw, JawCommand::close);
}

TEST(InputScriptRepeat, OnceIsTheScriptItself) {
  const InputScript once = parse_input_script(kCycle, "cycle.script");
  const InputScript again = repeat_input_script(once, 1, 2.0);
  EXPECT_EQ(again.right.poses.size(), once.right.poses.size());
  EXPECT_DOUBLE_EQ(again.end_time(), once.end_time());
}

TEST(InputScriptRepeat, RefusesOverlappingCopiesAndZeroPlays) {
  const InputScript once = parse_input_script(kCycle, "cycle.script");
  try {
    repeat_input_script(once, 2, 1.5);
    FAIL() << "copies overlapping";
  } catch (const InputScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("cycle.script: the repeat period (1.500000 s) is shorter"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(repeat_input_script(once, 0, 3.0), InputScriptError);
  EXPECT_THROW(repeat_input_script(once, 2, std::nan("")), InputScriptError);
}

}  // namespace
}  // namespace imasim::surgery
