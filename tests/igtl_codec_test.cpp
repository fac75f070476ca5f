// OpenIGTLink messages in and out: poses in millimetres become metres, buttons and the pedal
// arrive as SENSOR values, forces leave as SENSOR values in newtons; malformed, truncated,
// replayed and oversized messages are refused, counted, and change nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "devices/igtl_codec.hpp"

namespace imasim::devices {
namespace {

struct Message {
  std::vector<std::uint8_t> bytes;
  const std::uint8_t* header() const { return bytes.data(); }
  const std::uint8_t* body() const { return bytes.data() + kIgtlHeaderBytes; }
  std::size_t body_bytes() const { return bytes.size() - kIgtlHeaderBytes; }
};

bool apply(IgtlDecoder& d, const Message& m, ConsoleInput& in) {
  return d.apply(m.header(), m.body(), m.body_bytes(), in);
}

Pose turned_pose(const Vec3& translation_m) {
  Pose p;
  p.rotation = axis_angle(Vec3(0, 0, 1), 0.5);
  p.translation = translation_m;
  return p;
}

// A left-hand pose at x (m) stamped `stamp`, arriving at `arrival` on the loop's clock (unit: s).
bool left_pose_at(IgtlDecoder& d, ConsoleInput& in, double stamp, double arrival, double x) {
  const Message m{encode_pose("LeftHand", turned_pose(Vec3(x, 0, 0)), stamp)};
  return d.apply(m.header(), m.body(), m.body_bytes(), in, arrival);
}

TEST(IgtlCodec, APoseInMillimetresArrivesInMetresWithItsVelocity) {
  IgtlDecoder d;
  ConsoleInput in;
  ASSERT_TRUE(apply(d, {encode_pose("LeftHand", turned_pose(Vec3(0.01, -0.02, 0.03)), 10.0)}, in));
  EXPECT_TRUE(in.left.has_pose);
  EXPECT_FALSE(in.right.has_pose);
  EXPECT_TRUE(in.left.pose.translation.isApprox(Vec3(0.01, -0.02, 0.03), 1e-6));
  EXPECT_TRUE(in.left.pose.rotation.isApprox(axis_angle(Vec3(0, 0, 1), 0.5), 1e-6));
  // 1 mm along x in 1 ms (the time stamp's 2^-32 s steps): 1 m/s.
  ASSERT_TRUE(
      apply(d, {encode_pose("LeftHand", turned_pose(Vec3(0.011, -0.02, 0.03)), 10.001)}, in));
  EXPECT_NEAR(in.left.velocity.x(), 1.0, 1e-3);
  EXPECT_NEAR(in.left.time_s, 10.001, 1e-6);
  // The wire carries millimetres: the packed matrix's translation reads 11 (mm).
  const std::vector<std::uint8_t> bytes =
      encode_pose("RightHand", turned_pose(Vec3(0.011, 0, 0)), 1.0);
  float x_mm = 0;
  std::uint32_t big = 0;
  std::memcpy(&big, bytes.data() + kIgtlHeaderBytes + 9 * 4, 4);  // 10th float: x position
  big = __builtin_bswap32(big);
  std::memcpy(&x_mm, &big, 4);
  EXPECT_NEAR(x_mm, 11.0f, 1e-4f);
  EXPECT_EQ(d.counters().accepted, 2u);
}

TEST(IgtlCodec, ButtonsAndPedalArriveAsSensorValues) {
  IgtlDecoder d;
  ConsoleInput in;
  ASSERT_TRUE(apply(d, {encode_values("RightButtons", {1, 0.75}, 1.0)}, in));
  EXPECT_TRUE(in.right.clutch);
  EXPECT_EQ(in.right.jaw, Real(0.75));
  ASSERT_TRUE(apply(d, {encode_values("Pedal", {2}, 1.0)}, in));
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  ASSERT_TRUE(apply(d, {encode_values("Pedal", {0}, 1.1)}, in));
  EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
}

TEST(IgtlCodec, ABadClockCannotBreakAnOutgoingMessage) {
  // The header's seconds are 32 bits: a time past 2106, negative or NaN is clamped, not UB.
  IgtlDecoder d;
  for (const double t : {1e12, -5.0, double(NAN)}) {
    const std::vector<std::uint8_t> bytes = encode_force("LeftForce", Vec3(1, 0, 0), t);
    const std::optional<IgtlHeader> h = d.read_header(bytes.data());
    ASSERT_TRUE(h) << t;
    EXPECT_TRUE(std::isfinite(h->time_s)) << t;
    EXPECT_LE(h->time_s, 4294967296.0) << t;
  }
}

TEST(IgtlCodec, AForceLeavesAsASensorMessageInNewtons) {
  const std::vector<std::uint8_t> bytes = encode_force("LeftForce", Vec3(0.5, -1.25, 3), 2.0);
  // Read back as a peer would: a SENSOR named LeftForce with three values.
  IgtlNames names;
  names.pedal = "LeftForce";  // any mapped SENSOR name unpacks; the values are what matter
  IgtlDecoder d(names);
  const std::optional<IgtlHeader> h = d.read_header(bytes.data());
  ASSERT_TRUE(h);
  EXPECT_EQ(h->type, "SENSOR");
  EXPECT_EQ(h->device, "LeftForce");
  EXPECT_EQ(h->body_bytes, 10u + 3 * 8);
  double z = 0;
  std::uint64_t big = 0;
  std::memcpy(&big, bytes.data() + kIgtlHeaderBytes + 10 + 2 * 8, 8);
  big = __builtin_bswap64(big);
  std::memcpy(&z, &big, 8);
  EXPECT_EQ(z, 3.0);
}

TEST(IgtlCodec, MalformedTruncatedReplayedAndOversizedMessagesAreRefusedAndCounted) {
  IgtlDecoder d;
  ConsoleInput in;
  const Message good{encode_pose("LeftHand", turned_pose(Vec3(0.01, 0, 0)), 5.0)};
  ASSERT_TRUE(apply(d, good, in));
  const ConsoleInput before = in;
  auto refused = [&](const Message& m, IgtlRefusal why) {
    const std::uint64_t count = d.counters().refused[std::size_t(why)];
    EXPECT_FALSE(apply(d, m, in)) << igtl_refusal_name(why);
    EXPECT_EQ(d.counters().refused[std::size_t(why)], count + 1) << igtl_refusal_name(why);
    EXPECT_EQ(in.left.pose.translation, before.left.pose.translation);
  };
  // Replayed: the same message again, and an older one.
  refused(good, IgtlRefusal::out_of_order);
  refused({encode_pose("LeftHand", turned_pose(Vec3(0.02, 0, 0)), 4.0)}, IgtlRefusal::out_of_order);
  // A flipped body byte: the CRC no longer matches.
  Message flipped{encode_pose("LeftHand", turned_pose(Vec3(0.02, 0, 0)), 6.0)};
  flipped.bytes[kIgtlHeaderBytes + 3] ^= 0x40;
  refused(flipped, IgtlRefusal::bad_body);
  // Truncated: a body shorter than its header says.
  Message truncated{encode_pose("LeftHand", turned_pose(Vec3(0.02, 0, 0)), 6.0)};
  truncated.bytes.resize(truncated.bytes.size() - 5);
  refused(truncated, IgtlRefusal::bad_body);
  // A header declaring a 1 GB body.
  Message oversized{encode_values("Pedal", {1}, 7.0)};
  const std::uint64_t huge = __builtin_bswap64(std::uint64_t(1) << 30);
  std::memcpy(oversized.bytes.data() + 42, &huge, 8);  // the body size field
  refused(oversized, IgtlRefusal::oversized);
  // Not a header at all.
  refused({std::vector<std::uint8_t>(kIgtlHeaderBytes + 4, 0xff)}, IgtlRefusal::bad_header);
  // Names and types imasim does not read.
  refused({encode_pose("Stylus", turned_pose(Vec3::Zero()), 8.0)}, IgtlRefusal::unknown_device);
  refused({encode_values("LeftHand", {1, 2, 3}, 8.0)}, IgtlRefusal::unknown_device);
  // Values: a scaled "rotation", a NaN, a hand 5 m away, a jaw beyond closed, an unknown mode.
  Pose scaled = turned_pose(Vec3::Zero());
  scaled.rotation *= 2;
  refused({encode_pose("LeftHand", scaled, 9.0)}, IgtlRefusal::bad_values);
  refused({encode_pose("LeftHand", turned_pose(Vec3(NAN, 0, 0)), 9.0)}, IgtlRefusal::bad_values);
  refused({encode_pose("LeftHand", turned_pose(Vec3(5, 0, 0)), 9.0)}, IgtlRefusal::bad_values);
  refused({encode_values("LeftButtons", {0, 1.5}, 9.0)}, IgtlRefusal::bad_values);
  refused({encode_values("Pedal", {3}, 9.0)}, IgtlRefusal::bad_values);
  refused({encode_values("Pedal", {NAN}, 9.0)}, IgtlRefusal::bad_values);
  EXPECT_EQ(d.counters().accepted, 1u);
  EXPECT_EQ(d.counters().refused_total(), 14u);
}

// A tracker that stamps no time (the protocol's unused stamp is 0, and common tracking servers
// send it): every pose is followed in the order it arrives, timed by its arrival, none refused
// as out of order after the first (the instrument froze).
TEST(IgtlCodec, UnstampedMessagesAreTakenInArrivalOrderAndTimedOnArrival) {
  IgtlDecoder d;
  ConsoleInput in;
  for (int k = 0; k < 5; ++k) {
    const Message m{encode_pose("LeftHand", turned_pose(Vec3(0.001 * k, 0, 0)), 0.0)};
    ASSERT_TRUE(d.apply(m.header(), m.body(), m.body_bytes(), in, 1.0 + 0.01 * k)) << k;
    const Message b{encode_values("LeftButtons", {0, 0.1 * k}, 0.0)};
    ASSERT_TRUE(d.apply(b.header(), b.body(), b.body_bytes(), in, 1.0 + 0.01 * k)) << k;
  }
  EXPECT_NEAR(in.left.pose.translation.x(), 0.004, 1e-6);
  EXPECT_NEAR(in.left.velocity.x(), 0.1, 1e-3);  // 1 mm per 10 ms of arrival
  EXPECT_DOUBLE_EQ(in.left.time_s, 1.04);
  EXPECT_NEAR(in.left.jaw, 0.4, 1e-9);
  EXPECT_EQ(d.counters().refused_total(), 0u);
  // A stamped sender on the same decoder keeps its order check.
  const Message late{encode_pose("RightHand", turned_pose(Vec3::Zero()), 5.0)};
  EXPECT_TRUE(d.apply(late.header(), late.body(), late.body_bytes(), in, 2.0));
  EXPECT_FALSE(d.apply(late.header(), late.body(), late.body_bytes(), in, 2.1));
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::out_of_order)], 1u);
}

// One pose stamped 2^32 - 1 s was adopted as the device's last stamp and every later pose was
// refused as out of order for the rest of the session. A stamp more than 1 s ahead of the
// sender's clock (stamp minus arrival, as its first stamped message showed) is refused instead.
TEST(IgtlCodec, AStampFarInTheFutureIsRefusedNotAdopted) {
  IgtlDecoder d;
  ConsoleInput in;
  auto at = [&](double stamp, double arrival, double x) {
    return left_pose_at(d, in, stamp, arrival, x);
  };
  ASSERT_TRUE(at(100.0, 10.0, 0.001));  // the sender's clock runs 90 s ahead of the loop's
  EXPECT_FALSE(at(4294967295.0, 10.01, 0.5));
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::future_stamp)], 1u);
  EXPECT_TRUE(at(100.02, 10.02, 0.002));  // followed still
  EXPECT_TRUE(at(100.53, 10.04, 0.003));  // half a second of jitter ahead is not the future
  EXPECT_NEAR(in.left.pose.translation.x(), 0.003, 1e-7);
  // A replayed old message, alone, is refused as out of order and changes nothing.
  EXPECT_FALSE(at(50.0, 10.05, 0.4));
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::out_of_order)], 1u);
  EXPECT_TRUE(at(100.6, 10.06, 0.004));
  // Without a clock (arrival 0) stamps are only ordered.
  IgtlDecoder plain;
  const Message far{encode_pose("LeftHand", turned_pose(Vec3::Zero()), 4294967295.0)};
  EXPECT_TRUE(plain.apply(far.header(), far.body(), far.body_bytes(), in));
}

// A first message stamped far ahead set the sender's clock; the stamps after it agree with each
// other and are behind it. After half a second of them the clock and the order start again from
// them: the device is followed, not locked out.
TEST(IgtlCodec, AnOddFirstStampIsForgottenOnceTheSenderAgreesWithItself) {
  IgtlDecoder d;
  ConsoleInput in;
  auto at = [&](double stamp, double arrival, double x) {
    return left_pose_at(d, in, stamp, arrival, x);
  };
  ASSERT_TRUE(at(4294967295.0, 1.0, 0.001));
  int refused = 0, first_followed = -1;
  for (int k = 1; k <= 100; ++k) {
    const bool taken = at(20.0 + 0.01 * k, 1.0 + 0.01 * k, 0.001 * k);
    if (!taken) ++refused;
    if (taken && first_followed < 0) first_followed = k;
  }
  EXPECT_EQ(first_followed, 51);  // 0.5 s of arrival after the first one behind (k = 1)
  EXPECT_EQ(refused, 50);
  EXPECT_NEAR(in.left.pose.translation.x(), 0.1, 1e-7);
  EXPECT_DOUBLE_EQ(in.left.time_s, 21.0);
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::out_of_order)], 50u);
}

// Refusals are told apart by the sender's device name, so that a user can see that a tracker
// called "Tracker" is not mapped to a hand; past the table's room they are counted as others.
TEST(IgtlCodec, RefusalsAreCountedByDeviceNameAndReason) {
  IgtlDecoder d;
  ConsoleInput in;
  for (int k = 0; k < 3; ++k)
    EXPECT_FALSE(apply(d, {encode_pose("Tracker", turned_pose(Vec3::Zero()), 1.0 + k)}, in));
  EXPECT_FALSE(apply(d, {encode_pose("LeftHand", turned_pose(Vec3(NAN, 0, 0)), 1.0)}, in));
  EXPECT_FALSE(apply(d, {std::vector<std::uint8_t>(kIgtlHeaderBytes + 4, 0xff)}, in));
  const IgtlCounters& c = d.counters();
  ASSERT_EQ(c.named, 3u);
  EXPECT_STREQ(c.refused_names[0].name.data(), "Tracker");
  EXPECT_EQ(c.refused_names[0].count, 3u);
  EXPECT_STREQ(c.refused_names[1].name.data(), "LeftHand");
  EXPECT_EQ(c.refused_names[1].count, 1u);
  EXPECT_STREQ(c.refused_names[2].name.data(), "");  // no header to read a name from
  EXPECT_EQ(c.reasons_seen(), (1u << unsigned(IgtlRefusal::unknown_device)) |
                                  (1u << unsigned(IgtlRefusal::bad_values)) |
                                  (1u << unsigned(IgtlRefusal::bad_header)));
  for (std::size_t k = 0; k < kIgtlRefusedNames + 4; ++k)
    apply(d, {encode_values("Stranger" + std::to_string(k), {1}, 1.0)}, in);
  EXPECT_EQ(c.named, kIgtlRefusedNames);
  EXPECT_EQ(c.refused_others, 7u);  // 20 new names, 13 places left
  EXPECT_EQ(c.refused_total(), 25u);
}

// Messages the fuzzer found (fuzz/corpus/igtl_message/regression_*): a SENSOR body shorter than
// its value count and a TRANSFORM whose header declares a short body made the library read past
// them. Both are refused before the library reads them.
TEST(IgtlCodec, BodiesShorterThanTheLibraryReadsAreRefused) {
  for (const char* name : {"regression_sensor_count", "regression_transform_size"}) {
    std::ifstream in(std::string(IMASIM_SOURCE_DIR "/fuzz/corpus/igtl_message/") + name,
                     std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                          std::istreambuf_iterator<char>());
    ASSERT_GE(bytes.size(), kIgtlHeaderBytes) << name;
    IgtlDecoder d;
    ConsoleInput input;
    std::size_t at = 0, refused = 0;
    while (bytes.size() - at >= kIgtlHeaderBytes) {
      const std::optional<IgtlHeader> h = d.read_header(bytes.data() + at);
      if (!h) break;
      const std::size_t given =
          std::min<std::size_t>(h->body_bytes, bytes.size() - at - kIgtlHeaderBytes);
      if (!d.apply(bytes.data() + at, bytes.data() + at + kIgtlHeaderBytes, given, input))
        ++refused;
      at += kIgtlHeaderBytes + given;
    }
    EXPECT_GT(refused, 0u) << name;
    EXPECT_GT(d.counters().refused[std::size_t(IgtlRefusal::bad_body)], 0u) << name;
  }
  // The same by construction: a SENSOR declaring 200 values with a body of one.
  Message short_sensor{encode_values("Pedal", {1}, 1.0)};
  short_sensor.bytes[kIgtlHeaderBytes] = 200;
  IgtlDecoder d;
  ConsoleInput input;
  EXPECT_FALSE(apply(d, short_sensor, input));
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::bad_body)], 1u);
}

TEST(IgtlCodec, ToolPosesAndThePedalsPowerArriveAsSuch) {
  IgtlDecoder d;
  ConsoleInput in;
  // A tracker on the hook sends its hinge in the scene frame.
  ASSERT_TRUE(apply(d, {encode_pose("RightTool", turned_pose(Vec3(0.01, 0.02, 0.05)), 3.0)}, in));
  EXPECT_EQ(in.right.frame, PoseFrame::tool);
  EXPECT_TRUE(in.right.pose.translation.isApprox(Vec3(0.01, 0.02, 0.05), 1e-6));
  ASSERT_TRUE(apply(d, {encode_pose("LeftHand", turned_pose(Vec3(0, 0, 0)), 3.0)}, in));
  EXPECT_EQ(in.left.frame, PoseFrame::hand);
  EXPECT_FALSE(in.left.has_buttons);
  ASSERT_TRUE(apply(d, {encode_values("LeftButtons", {0, 0.5}, 3.0)}, in));
  EXPECT_TRUE(in.left.has_buttons);
  // [mode, power]: coagulation at 25 W; a power past the generator's 300 W is refused.
  ASSERT_TRUE(apply(d, {encode_values("Pedal", {2, 25}, 3.0)}, in));
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  EXPECT_EQ(in.power_w, 25);
  EXPECT_FALSE(apply(d, {encode_values("Pedal", {1, 400}, 3.1)}, in));
  EXPECT_FALSE(apply(d, {encode_values("Pedal", {1, 20, 3}, 3.2)}, in));
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  EXPECT_EQ(d.counters().refused[std::size_t(IgtlRefusal::bad_values)], 2u);
}

}  // namespace
}  // namespace imasim::devices
