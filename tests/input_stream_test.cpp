// Recorded device streams (console/input_stream.hpp): a step's input survives the text exactly,
// and a bad file is refused with its path, line and the field at fault.
#include <gtest/gtest.h>

#include "console/input_stream.hpp"

namespace imasim::console {
namespace {

session::SessionInput sample_input() {
  session::SessionInput in;
  in.left.source = surgery::PoseSource::hand;
  in.left.pose.translation = Vec3(0.1 / 3, -1e-7, 0.0123456789);
  in.left.pose.rotation = axis_angle(Vec3(1, 2, 3).normalized(), 0.7);
  in.left.jaw = surgery::JawCommand::close;
  in.left.clutch = true;
  in.right.source = surgery::PoseSource::tool;
  in.right.pose.translation = Vec3(0.0125, -0.0181, 0.055);
  in.right.pedal = surgery::PedalMode::cut;
  in.right.power = 37.5;
  in.camera.optics = 0.5235987755982988;
  in.camera.roll = 0.25;
  return in;
}

TEST(InputStream, AStepsInputSurvivesTheTextExactly) {
  const session::SessionInput in = sample_input();
  const std::string text = "# a comment\n" + format_input_line(0, in) + "\n" +
                           format_input_line(1, session::SessionInput{}) + "\n";
  const std::vector<session::SessionInput> back = parse_input_stream(text, "s.stream");
  ASSERT_EQ(back.size(), 2u);
  const session::SessionInput& a = back[0];
  EXPECT_EQ(a.left.source, in.left.source);
  EXPECT_EQ(a.left.pose.translation, in.left.pose.translation);  // bit for bit
  EXPECT_EQ(a.left.pose.rotation, in.left.pose.rotation);
  EXPECT_EQ(a.left.jaw, in.left.jaw);
  EXPECT_EQ(a.left.clutch, in.left.clutch);
  EXPECT_EQ(a.right.source, in.right.source);
  EXPECT_EQ(a.right.pose.translation, in.right.pose.translation);
  EXPECT_EQ(a.right.pedal, in.right.pedal);
  EXPECT_EQ(a.right.power, in.right.power);
  EXPECT_EQ(a.camera.optics, in.camera.optics);
  EXPECT_FALSE(a.camera.insertion.has_value());
  EXPECT_EQ(a.camera.roll, in.camera.roll);
  EXPECT_EQ(back[1].left.source, surgery::PoseSource::none);
}

TEST(InputStream, TheStepsOfALostDeviceAreMarkedAndReadBack) {
  session::SessionInput in = sample_input();
  const std::string plain = format_input_line(0, in);
  EXPECT_EQ(plain.find("lost"), std::string::npos);  // streams without a loss read as before
  in.right.device_lost = true;
  const std::string right = format_input_line(1, in);
  EXPECT_EQ(right.substr(right.size() - 11), " lost:right");
  in.left.device_lost = true;
  const std::string both = format_input_line(2, in);
  const auto back = parse_input_stream(plain + "\n" + right + "\n" + both + "\n", "s.stream");
  ASSERT_EQ(back.size(), 3u);
  EXPECT_FALSE(back[0].left.device_lost || back[0].right.device_lost);
  EXPECT_FALSE(back[1].left.device_lost);
  EXPECT_TRUE(back[1].right.device_lost);
  EXPECT_TRUE(back[2].left.device_lost && back[2].right.device_lost);
  const std::string wrong = plain + " lost:feet";
  try {
    parse_input_stream(wrong, "bad.stream");
    ADD_FAILURE() << "accepted";
  } catch (const InputStreamError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "bad.stream:1: unexpected fields after the camera's ('lost:feet'"),
              std::string::npos)
        << e.what();
  }
}

std::string error_of(const std::string& text) {
  try {
    parse_input_stream(text, "bad.stream");
  } catch (const InputStreamError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(InputStream, BadLinesNameTheFileLineAndField) {
  const std::string good = format_input_line(0, sample_input());
  auto replaced = [&](const std::string& from, const std::string& to) {
    const std::size_t at = good.find(from);
    if (at == std::string::npos) {
      ADD_FAILURE() << "no '" << from << "' in the line";
      return good;
    }
    return good.substr(0, at) + to + good.substr(at + from.size());
  };
  std::string second_line = "\n";
  second_line += replaced(" hand ", " foot ");
  EXPECT_NE(error_of(second_line)
                .find("bad.stream:2: left pose source "
                      "'foot'"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(" cut ", " burn ")).find("bad.stream:1: right pedal 'burn'"),
            std::string::npos);
  EXPECT_NE(error_of(good.substr(0, good.size() / 2)).find("bad.stream:1: missing"),
            std::string::npos);
  EXPECT_NE(error_of(good + " extra").find("unexpected fields"), std::string::npos);
  std::string renumbered = good;
  renumbered[0] = '1';
  EXPECT_NE(error_of(renumbered).find("step 1 out of order; expected 0"), std::string::npos);
  EXPECT_NE(error_of(replaced(" -1 1 ", " -1 7 ")).find("left clutch '7'"), std::string::npos);
  EXPECT_NE(error_of(replaced(" 0x1.4p+5 ", " nan ")).find("not a finite number"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(" 0x1.4p+5 ", " 400 ")).find("left power is outside"),
            std::string::npos);
  // A rotation that is not one.
  session::SessionInput skewed = sample_input();
  skewed.left.pose.rotation *= 2;
  EXPECT_NE(error_of(format_input_line(0, skewed)).find("left rotation is not a rotation"),
            std::string::npos);
  // A file that is not there names itself.
  try {
    load_input_stream("/nonexistent/x.stream");
    ADD_FAILURE() << "accepted";
  } catch (const InputStreamError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.stream"), std::string::npos);
  }
}

}  // namespace
}  // namespace imasim::console
