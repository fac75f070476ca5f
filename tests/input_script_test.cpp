// The headless input script: the format (comments, CRLF, tabs), pose interpolation (exact
// midpoints, slerp the short way), piecewise constant commands, every error message with its
// line, fuzzed input that must parse or throw InputScriptError, and bit-for-bit determinism.
#include "surgery/input_script.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "math/angles.hpp"

namespace imasim::surgery {
namespace {

// Commands written arm by arm instead of in time order: line 6 goes back to 0, an error.
constexpr std::string_view kUnsortedExample =
    "# Grasp the fascia with the left forceps, then cut with the right hook.\n"
    "0.00  left   hand   0 0 0  0 0 0     # console hand pose: x y z (m), rx ry rz (rad)\n"
    "0.50  left   hand   0.03 0 0  0 0 0\n"
    "0.50  left   jaw    close\n"
    "1.00  left   clutch on\n"
    "0.00  right  tool   -0.02 -0.01 0.07  0 0 0   # hinge pose in the scene frame\n"
    "0.00  right  pedal  cut\n"
    "0.00  right  power  40\n"
    "0.00  camera optics 30\n"
    "0.00  camera insertion 0.05\n"
    "0.00  camera roll 0.2\n";

// The example of docs/input_script.md.
constexpr std::string_view kExample =
    "# Grasp the fascia with the left forceps, then cut with the right hook.\n"
    "0.00  left   hand   0 0 0  0 0 0     # console hand pose: x y z (m), rx ry rz (rad)\n"
    "0.00  right  tool   -0.02 -0.01 0.07  0 0 0   # hinge pose in the scene frame\n"
    "0.00  right  pedal  cut\n"
    "0.00  right  power  35\n"
    "0.00  camera optics 30\n"
    "0.00  camera insertion 0.05\n"
    "0.00  camera roll 0.2\n"
    "0.50  left   hand   0.03 0 0  0 0 0\n"
    "0.50  left   jaw    close\n"
    "1.00  left   clutch on\n"
    "1.00  right  tool   -0.02 -0.01 0.05  0.2 0 0\n";

std::string error_of(std::string_view text, const std::string& path = "script.txt") {
  try {
    parse_input_script(text, path);
  } catch (const InputScriptError& e) {
    return e.what();
  }
  return "(parsed without error)";
}

::testing::AssertionResult fails_with(std::string_view text, const std::string& expected) {
  const std::string message = error_of(text);
  if (message.find(expected) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected '" << expected << "' in '" << message << "'";
}

// `n` valid lines at time 0, so that the next line is line n + 1.
std::string lines(int n) {
  std::string s;
  for (int i = 0; i < n; ++i)
    s += "0 left jaw hold\n";
  return s;
}

bool finite(const Pose& p) {
  return p.rotation.allFinite() && p.translation.allFinite();
}

TEST(InputScript, TheDocsExampleOutOfOrderNamesItsLine) {
  EXPECT_TRUE(fails_with(kUnsortedExample,
                         "script.txt:6: time 0.00 is earlier than the previous line's "
                         "1.00"));
}

TEST(InputScript, AFullScriptParsesWithEveryField) {
  const InputScript s = parse_input_script(kExample, "example.txt");
  EXPECT_EQ(s.path, "example.txt");
  EXPECT_EQ(s.end_time(), 1.0);
  ASSERT_EQ(s.left.poses.size(), 2u);
  ASSERT_EQ(s.right.poses.size(), 2u);
  EXPECT_EQ(s.left.source, PoseSource::hand);
  EXPECT_EQ(s.right.source, PoseSource::tool);

  static_assert(std::is_same_v<decltype(InstrumentInput::jaw), JawCommand>);
  static_assert(std::is_same_v<decltype(InstrumentInput::clutch), bool>);
  static_assert(std::is_same_v<decltype(InstrumentInput::pedal), PedalMode>);
  static_assert(std::is_same_v<decltype(InstrumentInput::power), Real>);
  static_assert(std::is_same_v<decltype(CameraInput::insertion), std::optional<Real>>);

  const InstrumentInput left0 = sample_instrument(s.left, 0.0);
  EXPECT_EQ(left0.source, PoseSource::hand);
  EXPECT_EQ(left0.pose.translation, Vec3(0, 0, 0));
  EXPECT_EQ(left0.pose.rotation, Mat3::Identity());
  EXPECT_EQ(left0.jaw, JawCommand::hold);
  EXPECT_FALSE(left0.clutch);
  EXPECT_EQ(left0.pedal, PedalMode::off);
  EXPECT_EQ(left0.power, 40);

  const InstrumentInput left1 = sample_instrument(s.left, 1.0);
  EXPECT_EQ(left1.pose.translation, Vec3(0.03, 0, 0));
  EXPECT_EQ(left1.jaw, JawCommand::close);
  EXPECT_TRUE(left1.clutch);

  const InstrumentInput right0 = sample_instrument(s.right, 0.0);
  EXPECT_EQ(right0.source, PoseSource::tool);
  EXPECT_EQ(right0.pose.translation, Vec3(-0.02, -0.01, 0.07));
  EXPECT_EQ(right0.pedal, PedalMode::cut);
  EXPECT_EQ(right0.power, 35);
  EXPECT_EQ(right0.jaw, JawCommand::hold);
  const InstrumentInput right1 = sample_instrument(s.right, 1.0);
  EXPECT_EQ(right1.pose.translation, Vec3(-0.02, -0.01, 0.05));
  EXPECT_NEAR((right1.pose.rotation - axis_angle(Vec3::UnitX(), 0.2)).norm(), 0, 1e-15);

  const CameraInput cam = sample_camera(s.camera, 0.0);
  EXPECT_EQ(cam.optics, degrees_to_radians(30));  // degrees in the file, radians stored
  ASSERT_TRUE(cam.insertion.has_value());
  EXPECT_EQ(*cam.insertion, 0.05);
  ASSERT_TRUE(cam.roll.has_value());
  EXPECT_EQ(*cam.roll, 0.2);
}

TEST(InputScript, CommentsBlankLinesTabsCrlfAndNoFinalNewline) {
  const std::string text =
      "\r\n"
      "   # a comment line\r\n"
      "\t\t\r\n"
      "0\tleft\thand\t0.01 0.02\t0.03 0 0 0#glued comment\r\n"
      "0.5 left jaw open   \t # trailing blanks\r\n"
      "\r\n"
      "1 left jaw close";  // no final newline
  const InputScript s = parse_input_script(text, "crlf.txt");
  ASSERT_EQ(s.left.poses.size(), 1u);
  EXPECT_EQ(s.left.poses[0].pose.translation, Vec3(0.01, 0.02, 0.03));
  ASSERT_EQ(s.left.jaw.size(), 2u);
  EXPECT_EQ(s.left.jaw[1].value, JawCommand::close);
  EXPECT_EQ(s.left.jaw[1].time, 1.0);
  EXPECT_EQ(s.end_time(), 1.0);
  // CRLF counts one line per line end.
  const std::string bad = "0 left jaw open\r\n\r\n# c\r\n0 left jaw shut\r\n";
  EXPECT_TRUE(fails_with(bad, "script.txt:4: jaw expects open, close or hold, got 'shut'"));
  // A CR without LF is not a line end: it is part of the token.
  EXPECT_TRUE(fails_with("0 left jaw open\r0 left jaw close\n", "script.txt:1: jaw expects 1"));
}

TEST(InputScript, AnEmptyScriptIsValid) {
  for (const std::string_view text : {std::string_view(""), std::string_view("\n\n"),
                                      std::string_view("# nothing\n  \t\n# else")}) {
    const InputScript s = parse_input_script(text, "empty.txt");
    EXPECT_EQ(s.end_time(), 0.0);
    const InstrumentInput in = sample_instrument(s.left, 1.0);
    EXPECT_EQ(in.source, PoseSource::none);
    EXPECT_EQ(in.pose.rotation, Mat3::Identity());
    EXPECT_EQ(in.pose.translation, Vec3::Zero());
    EXPECT_EQ(in.jaw, JawCommand::hold);
    EXPECT_FALSE(in.clutch);
    EXPECT_EQ(in.pedal, PedalMode::off);
    EXPECT_EQ(in.power, 40);
    const CameraInput cam = sample_camera(s.camera, 1.0);
    EXPECT_EQ(cam.optics, 0);
    EXPECT_FALSE(cam.insertion.has_value());
    EXPECT_FALSE(cam.roll.has_value());
  }
}

TEST(InputScript, PositionHalfwayIsTheExactMidpoint) {
  const InputScript s = parse_input_script(
      "1 right tool 0.01 -0.02 0.04 0 0 0\n3 right tool 0.03 0.02 -0.06 0 0 0\n", "p.txt");
  const InstrumentInput mid = sample_instrument(s.right, 2.0);
  EXPECT_EQ(mid.pose.translation.x(), 0.5 * (0.01 + 0.03));
  EXPECT_EQ(mid.pose.translation.y(), 0.0);
  EXPECT_EQ(mid.pose.translation.z(), 0.5 * (0.04 - 0.06));
  const InstrumentInput quarter = sample_instrument(s.right, 1.5);
  EXPECT_NEAR((quarter.pose.translation - Vec3(0.015, -0.01, 0.015)).norm(), 0, 1e-17);
}

TEST(InputScript, RotationHalfwayIsHalfTheAngle) {
  const Vec3 axes[] = {Vec3::UnitX(), Vec3::UnitZ(), Vec3(1, -2, 3).normalized(),
                       Vec3(-0.3, 0.1, 0.9).normalized()};
  for (const Vec3& axis : axes) {
    for (const Real angle : {0.001, 0.4, 1.5, 3.0}) {
      const Vec3 r = axis * angle;
      char text[256];
      std::snprintf(text, sizeof text,
                    "0 left hand 0 0 0 0 0 0\n2 left hand 0 0 0 %.17g %.17g %.17g\n", r.x(), r.y(),
                    r.z());
      const InputScript s = parse_input_script(text, "r.txt");
      const Mat3 half = sample_instrument(s.left, 1.0).pose.rotation;
      EXPECT_NEAR((half - axis_angle(axis, angle / 2)).norm(), 0, 1e-12) << text;
      const Mat3 end = sample_instrument(s.left, 2.0).pose.rotation;
      EXPECT_NEAR((end - axis_angle(axis, angle)).norm(), 0, 1e-12) << text;
    }
  }
}

TEST(InputScript, RotationTakesTheShortWayRound) {
  // 2 pi - 0.2 about z is -0.2 about z: halfway is -0.1, not pi - 0.1.
  char text[128];
  std::snprintf(text, sizeof text, "0 left hand 0 0 0 0 0 0\n1 left hand 0 0 0 0 0 %.17g\n",
                2 * kPi - 0.2);
  const InputScript s = parse_input_script(text, "r.txt");
  EXPECT_NEAR(
      (sample_instrument(s.left, 0.5).pose.rotation - axis_angle(Vec3::UnitZ(), -0.1)).norm(), 0,
      1e-12);
  // Between two non-identity keys too: 0.3 about x to 0.9 about x, a third of the way: 0.5.
  const InputScript t =
      parse_input_script("3 left hand 0 0 0 0.3 0 0\n6 left hand 0 0 0 0.9 0 0\n", "r.txt");
  EXPECT_NEAR(
      (sample_instrument(t.left, 4.0).pose.rotation - axis_angle(Vec3::UnitX(), 0.5)).norm(), 0,
      1e-12);
}

TEST(InputScript, PosesHoldBeforeTheFirstAndAfterTheLastKey) {
  const InputScript s =
      parse_input_script("1 left tool 0.01 0 0 0 0.5 0\n2 left tool 0.02 0 0 0 0 0.5\n", "h.txt");
  const Pose first = s.left.poses.front().pose, last = s.left.poses.back().pose;
  for (const double t : {-1e300, -1.0, 0.0, 0.999, 1.0}) {
    const Pose p = sample_instrument(s.left, t).pose;
    EXPECT_EQ(p.translation, first.translation) << t;
    EXPECT_EQ(p.rotation, first.rotation) << t;
  }
  for (const double t : {2.0, 2.5, 1e300}) {
    const Pose p = sample_instrument(s.left, t).pose;
    EXPECT_EQ(p.translation, last.translation) << t;
    EXPECT_EQ(p.rotation, last.rotation) << t;
  }
  EXPECT_NEAR((first.rotation - axis_angle(Vec3::UnitY(), 0.5)).norm(), 0, 1e-15);
}

TEST(InputScript, KeysAtTheSameTimeJumpAndTheLaterWins) {
  const InputScript s = parse_input_script(
      "0 left tool 0 0 0 0 0 0\n"
      "1 left tool 0.02 0 0 0 0 0\n"
      "1 left tool 0.04 0 0 0 0 1\n"
      "2 left tool 0.06 0 0 0 0 1\n",
      "j.txt");
  // Approaching 1 the pose heads for the first key at 1; from 1 on the second holds.
  EXPECT_EQ(sample_instrument(s.left, 0.5).pose.translation.x(), 0.01);
  EXPECT_EQ(sample_instrument(s.left, 1.0).pose.translation.x(), 0.04);
  EXPECT_NEAR(sample_instrument(s.left, 1.5).pose.translation.x(), 0.05, 1e-17);
  EXPECT_NEAR((sample_instrument(s.left, 1.0).pose.rotation - axis_angle(Vec3::UnitZ(), 1)).norm(),
              0, 1e-15);
  for (double t = -1; t <= 3; t += 0.125)
    EXPECT_TRUE(finite(sample_instrument(s.left, t).pose)) << t;

  // Every key at the same time: no interval at all. Before it the first key holds (as before
  // any first key), from it on the last.
  const InputScript same = parse_input_script(
      "0 right hand 0.01 0 0 0 0 0\n0 right hand 0.02 0 0 0 0 0\n0 right hand 0.03 0 0 1 0 0\n",
      "j.txt");
  for (const double t : {-1.0, 0.0, 1.0}) {
    const Pose p = sample_instrument(same.right, t).pose;
    EXPECT_TRUE(finite(p));
    EXPECT_EQ(p.translation.x(), t < 0 ? 0.01 : 0.03) << t;
  }
}

TEST(InputScript, DiscreteCommandsArePiecewiseConstant) {
  const InputScript s = parse_input_script(
      "0.0 right clutch on\n"
      "0.5 left jaw open\n"
      "1.0 left jaw close\n"
      "1.0 left jaw hold\n"  // same time: the later line applies from 1.0 on
      "2.0 right clutch off\n"
      "3.0 right pedal coag\n"
      "3.0 right power 50\n"
      "4.0 right pedal cut\n"
      "4.0 right power 30\n"
      "5.0 camera optics 30\n"
      "6.0 camera insertion 0.3\n"
      "6.0 camera roll -1.5\n"
      "7.0 camera optics 0\n"
      "7.0 camera insertion 0.01\n",
      "d.txt");
  const auto just_before = [](double t) { return std::nextafter(t, -1.0); };
  // Defaults before the first line.
  EXPECT_EQ(sample_instrument(s.left, 0.0).jaw, JawCommand::hold);
  EXPECT_EQ(sample_instrument(s.left, just_before(0.5)).jaw, JawCommand::hold);
  // At the line's time exactly, the new value.
  EXPECT_EQ(sample_instrument(s.left, 0.5).jaw, JawCommand::open);
  EXPECT_EQ(sample_instrument(s.left, just_before(1.0)).jaw, JawCommand::open);
  EXPECT_EQ(sample_instrument(s.left, 1.0).jaw, JawCommand::hold);
  EXPECT_EQ(sample_instrument(s.left, 99.0).jaw, JawCommand::hold);

  EXPECT_FALSE(sample_instrument(s.right, -1.0).clutch);
  EXPECT_TRUE(sample_instrument(s.right, 0.0).clutch);
  EXPECT_TRUE(sample_instrument(s.right, just_before(2.0)).clutch);
  EXPECT_FALSE(sample_instrument(s.right, 2.0).clutch);

  EXPECT_EQ(sample_instrument(s.right, just_before(3.0)).pedal, PedalMode::off);
  EXPECT_EQ(sample_instrument(s.right, just_before(3.0)).power, 40);
  EXPECT_EQ(sample_instrument(s.right, 3.0).pedal, PedalMode::coag);
  EXPECT_EQ(sample_instrument(s.right, 3.0).power, 50);
  EXPECT_EQ(sample_instrument(s.right, 3.5).pedal, PedalMode::coag);
  EXPECT_EQ(sample_instrument(s.right, 4.0).pedal, PedalMode::cut);
  EXPECT_EQ(sample_instrument(s.right, 4.0).power, 30);

  EXPECT_EQ(sample_camera(s.camera, just_before(5.0)).optics, 0);
  EXPECT_EQ(sample_camera(s.camera, 5.0).optics, degrees_to_radians(30));
  EXPECT_FALSE(sample_camera(s.camera, just_before(6.0)).insertion.has_value());
  EXPECT_FALSE(sample_camera(s.camera, just_before(6.0)).roll.has_value());
  EXPECT_EQ(sample_camera(s.camera, 6.0).insertion, Real(0.3));
  EXPECT_EQ(sample_camera(s.camera, 6.0).roll, Real(-1.5));
  EXPECT_EQ(sample_camera(s.camera, 7.0).optics, 0);
  EXPECT_EQ(sample_camera(s.camera, 7.0).insertion, Real(0.01));
  EXPECT_EQ(sample_camera(s.camera, 7.0).roll, Real(-1.5));
  EXPECT_EQ(s.end_time(), 7.0);
}

TEST(InputScript, ErrorMessagesNameTheFileLineAndField) {
  EXPECT_TRUE(fails_with(lines(6) + "0 left jaw shut\n",
                         "script.txt:7: jaw expects open, close or hold, got 'shut'"));
  EXPECT_TRUE(fails_with(lines(2) + "0 middle jaw open\n",
                         "script.txt:3: unknown target 'middle' (expected left, right or camera)"));
  EXPECT_TRUE(fails_with(lines(3) + "0 left hand 0 0 0 0 0\n",
                         "script.txt:4: hand expects 6 numbers (x y z rx ry rz), got 5"));
  EXPECT_TRUE(fails_with(lines(3) + "0 right tool 0 0 0 0 0 0 0\n",
                         "script.txt:4: tool expects 6 numbers (x y z rx ry rz), got 7"));
  EXPECT_TRUE(fails_with(lines(7) + "0.5 left jaw open\n0.4 left jaw close\n",
                         "script.txt:9: time 0.4 is earlier than the previous line's 0.5"));
  EXPECT_TRUE(
      fails_with(lines(1) + "0 right power 60\n", "script.txt:2: power 60 W is outside [30, 50]"));
  EXPECT_TRUE(fails_with(lines(1) + "0 right power 29.999\n",
                         "script.txt:2: power 29.999 W is outside [30, 50]"));
  EXPECT_TRUE(fails_with(lines(4) + "0 left grab\n",
                         "script.txt:5: unknown command 'grab' for left (expected hand, tool, "
                         "jaw, clutch, pedal or power)"));
  EXPECT_TRUE(fails_with("0 camera jaw open\n",
                         "script.txt:1: unknown command 'jaw' for camera (expected optics, "
                         "insertion or roll)"));
  EXPECT_TRUE(fails_with("0 camera optics 45\n",
                         "script.txt:1: optics expects 0 or 30 (degrees), got '45'"));
  EXPECT_TRUE(fails_with("0 camera insertion 0.5\n",
                         "script.txt:1: insertion 0.5 m is outside [0.01, 0.3]"));
  EXPECT_TRUE(fails_with("0 camera insertion 0.009\n",
                         "script.txt:1: insertion 0.009 m is outside [0.01, 0.3]"));
  EXPECT_TRUE(fails_with("0 camera roll inf\n",
                         "script.txt:1: roll expects a finite number (unit: rad), got 'inf'"));
  EXPECT_TRUE(fails_with("0 left clutch engaged\n",
                         "script.txt:1: clutch expects on or off, got 'engaged'"));
  EXPECT_TRUE(fails_with("0 right pedal burn\n",
                         "script.txt:1: pedal expects off, cut or coag, got 'burn'"));
  EXPECT_TRUE(fails_with("0 left jaw open close\n",
                         "script.txt:1: jaw expects 1 argument (open, close or hold), got 2"));
  EXPECT_TRUE(fails_with("\n\n0\n", "script.txt:3: missing target after the time"));
  EXPECT_TRUE(fails_with("0 right\n", "script.txt:1: missing command for right (expected hand"));
  EXPECT_TRUE(fails_with("0 camera\n", "script.txt:1: missing command for camera"));
  EXPECT_TRUE(fails_with("left 0 jaw open\n",
                         "script.txt:1: time expects a finite number >= 0 (unit: s), got 'left'"));
  EXPECT_TRUE(fails_with("-0.1 left jaw open\n",
                         "script.txt:1: time expects a finite number >= 0 (unit: s), got '-0.1'"));
  EXPECT_TRUE(
      fails_with("0 left hand 11 0 0 0 0 0\n", "script.txt:1: hand x 11 m is outside [-10, 10]"));
  EXPECT_TRUE(fails_with("0 left hand 0 0 0 1.7e308 -1.7e308 1.7e308\n",
                         "script.txt:1: hand rotation vector (rx ry rz) is too long"));
  // Case matters: commands are lower case.
  EXPECT_TRUE(fails_with("0 Left jaw open\n", "script.txt:1: unknown target 'Left'"));
  EXPECT_TRUE(fails_with("0 left jaw Open\n", "got 'Open'"));
}

TEST(InputScript, MixingHandAndToolFailsAtTheFirstMixingLine) {
  EXPECT_TRUE(fails_with(
      "0 left hand 0 0 0 0 0 0\n0 right tool 0 0 0 0 0 0\n1 left hand 0 0 0 0 0 0\n"
      "2 left tool 0 0 0 0 0 0\n",
      "script.txt:4: left mixes tool with hand (hand from line 1); a target uses either hand or "
      "tool"));
  EXPECT_TRUE(fails_with("0 right tool 0 0 0 0 0 0\n\n0 right hand 0 0 0 0 0 0\n",
                         "script.txt:3: right mixes hand with tool (tool from line 1)"));
}

TEST(InputScript, BadNumbersAreRefused) {
  const char* const bad[] = {"nan",    "-nan", "inf",  "-inf", "infinity", "1e999",   "-1e999",
                             "1e-400", "1.0x", "0x10", "1,5",  "--1",      "+-1",     "+",
                             "-",      ".",    "e5",   "1e",   "1..2",     "\xc2\xbd"};
  for (const char* b : bad) {
    const std::string got =
        std::string("got '") + (std::strcmp(b, "\xc2\xbd") == 0 ? "\\xc2\\xbd" : b) + "'";
    EXPECT_TRUE(fails_with(std::string(b) + " left jaw open\n", "script.txt:1: time expects") &&
                fails_with(std::string(b) + " left jaw open\n", got))
        << b;
    EXPECT_TRUE(fails_with("0 left hand 0 0 0 0 " + std::string(b) + " 0\n",
                           "script.txt:1: hand ry expects a finite number (unit: rad), " + got))
        << b;
    EXPECT_TRUE(fails_with("0 right tool " + std::string(b) + " 0 0 0 0 0\n",
                           "script.txt:1: tool x expects a finite number (unit: m), " + got))
        << b;
    EXPECT_TRUE(fails_with("0 right power " + std::string(b) + "\n",
                           "script.txt:1: power expects a finite number (unit: W), " + got))
        << b;
  }
  EXPECT_TRUE(fails_with("0 right power 1e999\n", "got '1e999' (out of range)"));
  // A missing (empty) number.
  EXPECT_TRUE(fails_with("0 right power\n",
                         "script.txt:1: power expects 1 argument (unit: W), "
                         "got 0"));
  EXPECT_TRUE(fails_with("0 camera roll   # gone\n", "script.txt:1: roll expects 1 argument"));
  // Accepted spellings: exponents, a leading '+' or '.', a trailing '.', -0.
  const InputScript s = parse_input_script(
      "-0 right power 4e1\n+.5 right power +45.\n1E0 camera insertion 5e-2\n", "ok.txt");
  EXPECT_EQ(s.right.power[0].value, 40);
  EXPECT_EQ(s.right.power[1].value, 45);
  EXPECT_FALSE(std::signbit(s.right.power[0].time));  // -0 stored as +0
  EXPECT_EQ(s.right.power[1].time, 0.5);
  EXPECT_EQ(s.camera.insertion[0].value, Real(0.05));
}

// A time in milliseconds ("5000" for 5 s) made a run 5000 s long, and 1e308 made the
// run's step count overflow; any time after an hour is refused with a hint.
TEST(InputScript, TimesAfterAnHourAreRefused) {
  EXPECT_TRUE(fails_with("0 right pedal off\n5000 right pedal cut\n",
                         "script.txt:2: time 5000 s is after the limit of 3600 s (an hour); "
                         "times are in seconds: was it written in milliseconds?"));
  EXPECT_TRUE(fails_with("1e308 left jaw open\n", "script.txt:1: time 1e308 s is after the limit"));
  EXPECT_TRUE(fails_with("1.7976931348623157e308 left jaw open\n", "is after the limit"));
  EXPECT_EQ(parse_input_script("3600 left jaw open\n", "ok.txt").end_time(), 3600.0);
}

TEST(InputScript, OnlyBoundedRegularFilesAreRead) {
  const auto error = [](const std::string& path) {
    try {
      load_input_script(path);
    } catch (const InputScriptError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(error("/dev/zero"),
            "/dev/zero: cannot open the input script: not a regular file (a device or a pipe is "
            "not read)");
  const std::string big = ::testing::TempDir() + "imasim_big_script_" + std::to_string(getpid());
  std::ofstream(big) << "0 left jaw open\n";
  std::filesystem::resize_file(big, (std::uint64_t(64) << 20) + 1);  // sparse: nothing written
  EXPECT_EQ(error(big), big + ": the input script is 67108865 bytes, above the limit of 64 MiB");
  std::filesystem::remove(big);
}

TEST(InputScript, BadTokensAreShownEscapedOnOneLine) {
  const std::string message = error_of(std::string("0 left jaw sh\x07ut\x1b[2J\x7f\\\n"));
  EXPECT_NE(message.find("script.txt:1: jaw expects open, close or hold, got "
                         "'sh\\x07ut\\x1b[2J\\x7f\\\\'"),
            std::string::npos)
      << message;
  const std::string nul = error_of(std::string("0 left\0 jaw open\n", 17));
  EXPECT_NE(nul.find("unknown target 'left\\x00'"), std::string::npos) << nul;
  // A megabyte token is cut short in the message.
  const std::string huge = "0 left jaw " + std::string(1 << 20, 'a') + "\n";
  const std::string cut = error_of(huge);
  EXPECT_NE(cut.find("got 'aaaa"), std::string::npos);
  EXPECT_NE(cut.find("...'"), std::string::npos);
  EXPECT_LT(cut.size(), 200u);
  // A path with a control character prints escaped too.
  EXPECT_EQ(error_of("x\n", "a\nb.txt").rfind("a\\x0ab.txt:1: ", 0), 0u);
}

TEST(InputScript, LoadsAFileAndNamesAMissingOne) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "imasim_input_script_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "script.txt").string();
  {
    std::ofstream out(path, std::ios::binary);
    out << kExample << "1.5 left jaw shut";
  }
  try {
    load_input_script(path);
    ADD_FAILURE() << "expected an error";
  } catch (const InputScriptError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":13: jaw expects open, close or hold, got 'shut'");
  }
  {
    std::ofstream out(path, std::ios::binary);
    out << kExample;
  }
  const InputScript s = load_input_script(path);
  EXPECT_EQ(s.path, path);
  EXPECT_EQ(s.end_time(), 1.0);
  EXPECT_EQ(sample_instrument(s.left, 1.0).jaw, JawCommand::close);

  const std::string missing = (dir / "missing.txt").string();
  try {
    load_input_script(missing);
    ADD_FAILURE() << "expected an error";
  } catch (const InputScriptError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open the input script: no such file");
  }
  try {  // a directory opens but reads nothing: not an empty script
    load_input_script(dir.string());
    ADD_FAILURE() << "expected an error";
  } catch (const InputScriptError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.string() + ": cannot open the input script: is a directory, not a file");
  }
  std::filesystem::remove_all(dir);
}

// Samples a parsed script at a few times: every pose finite and a rotation, every value in
// its range.
void expect_sound(const InputScript& s, const std::string& text) {
  const double end = s.end_time();
  ASSERT_TRUE(std::isfinite(end));
  for (const double t : {-1.0, 0.0, 0.3 * end, 0.5 * end, std::nextafter(end, 0.0), end, end + 1}) {
    for (const InstrumentTrack* track : {&s.left, &s.right}) {
      const InstrumentInput in = sample_instrument(*track, t);
      ASSERT_TRUE(finite(in.pose)) << text;
      ASSERT_LT((in.pose.rotation.transpose() * in.pose.rotation - Mat3::Identity()).norm(), 1e-9)
          << text;
      ASSERT_GE(in.power, 30);
      ASSERT_LE(in.power, 50);
    }
    const CameraInput cam = sample_camera(s.camera, t);
    ASSERT_TRUE(cam.optics == 0 || cam.optics == degrees_to_radians(30));
    ASSERT_TRUE(!cam.insertion || (*cam.insertion >= 0.01 && *cam.insertion <= 0.3));
    ASSERT_TRUE(!cam.roll || std::isfinite(*cam.roll));
  }
}

// Parses or throws InputScriptError with a one-line, printable "fuzz.txt:LINE: " message;
// returns whether it parsed.
bool parse_or_fail_cleanly(const std::string& text) {
  try {
    const InputScript s = parse_input_script(text, "fuzz.txt");
    expect_sound(s, text);
    return true;
  } catch (const InputScriptError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("fuzz.txt:", 0), 0u) << m;
    EXPECT_LT(m.size(), 400u) << m;
    for (const char c : m)
      EXPECT_TRUE(c >= 0x20 && c < 0x7f) << m;
  } catch (...) {
    ADD_FAILURE() << "an exception other than InputScriptError";
  }
  return false;
}

TEST(InputScript, RandomBytesParseOrFailCleanly) {
  std::mt19937_64 rng(20240607);
  const std::string alphabet = "0123456789.-+eE \t\n\r#abcdefghijklmnopqrstuvwxyz";
  int parsed = 0;
  for (int n = 0; n < 2000; ++n) {
    const std::size_t length = rng() % 300;
    std::string text(length, '\0');
    for (char& c : text)  // half from any byte, half from the script's own characters
      c = n % 2 ? static_cast<char>(rng() & 0xff) : alphabet[rng() % alphabet.size()];
    parsed += parse_or_fail_cleanly(text);
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(parsed, 0);  // blank and comment-only strings at least
}

TEST(InputScript, MutatedScriptsParseOrFailCleanly) {
  std::mt19937_64 rng(7);
  const std::string base(kExample);
  const std::string pieces[] = {
      " ",    "\t",    "\n",   "\r\n",  "#",     "-",       ".",    "e",    "9",
      "0",    "nan",   "inf",  "1e999", "1e308", "-1e-320", "hand", "tool", "camera",
      "left", "right", "open", "30",    "0.3",   "10",      "+",    "\x07", std::string(1, '\0')};
  int parsed = 0;
  for (int n = 0; n < 2000; ++n) {
    std::string text = base;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = text.empty() ? 0 : rng() % text.size();
      switch (rng() % 6) {
        case 0:  // overwrite a byte
          if (!text.empty()) text[at] = static_cast<char>(rng() & 0xff);
          break;
        case 1:  // insert a piece
          text.insert(at, pieces[rng() % std::size(pieces)]);
          break;
        case 2:  // erase a short run
          text.erase(at, rng() % 8);
          break;
        case 3: {  // duplicate the line holding `at`
          const std::size_t begin = at == 0 ? 0 : text.rfind('\n', at - 1) + 1;  // npos + 1 = 0
          const std::size_t end = text.find('\n', begin);
          const std::string line =
              text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
          text.insert(begin, line + "\n");
          break;
        }
        case 4:  // cut the text (no final newline, half a line)
          text.resize(at);
          break;
        default:  // overwrite a byte with a digit: mostly still valid, different numbers
          if (!text.empty()) text[at] = static_cast<char>('0' + rng() % 10);
          break;
      }
    }
    parsed += parse_or_fail_cleanly(text);
    if (::testing::Test::HasFailure()) break;
  }
  // Both outcomes are exercised.
  EXPECT_GT(parsed, 100);
  EXPECT_LT(parsed, 1900);
}

TEST(InputScript, ParsingTheSameTextTwiceGivesTheSameBits) {
  const std::string text = std::string(kExample) +
                           "1.25 left hand 0.011 -0.007 0.019 0.3 -1.1 2.9\n"
                           "2.75 left hand -0.013 0.021 0.002 -2.2 0.4 0.1\n";
  const InputScript a = parse_input_script(text, "a.txt"), b = parse_input_script(text, "b.txt");
  for (double t = -0.5; t < 3.5; t += 0.0625) {
    for (const auto side : {&InputScript::left, &InputScript::right}) {
      const InstrumentInput x = sample_instrument(a.*side, t), y = sample_instrument(b.*side, t);
      EXPECT_EQ(std::memcmp(x.pose.rotation.data(), y.pose.rotation.data(), sizeof(Mat3)), 0);
      EXPECT_EQ(std::memcmp(x.pose.translation.data(), y.pose.translation.data(), sizeof(Vec3)), 0);
      EXPECT_EQ(x.jaw, y.jaw);
      EXPECT_EQ(x.clutch, y.clutch);
      EXPECT_EQ(x.pedal, y.pedal);
      EXPECT_EQ(std::memcmp(&x.power, &y.power, sizeof(Real)), 0);
    }
    const CameraInput x = sample_camera(a.camera, t), y = sample_camera(b.camera, t);
    EXPECT_EQ(std::memcmp(&x.optics, &y.optics, sizeof(Real)), 0);
    EXPECT_EQ(x.insertion, y.insertion);
    EXPECT_EQ(x.roll, y.roll);
  }
}

TEST(InputScript, PedalModesHaveNames) {
  EXPECT_STREQ(to_string(PedalMode::off), "off");
  EXPECT_STREQ(to_string(PedalMode::cut), "cut");
  EXPECT_STREQ(to_string(PedalMode::coag), "coag");
}

}  // namespace
}  // namespace imasim::surgery
