// OpenIGTLink as the ecosystem uses it: several peers at once (a tracker for
// each hand, a pedal box), each with its own clock and order; a peer that vanishes loses the parts
// it drove and only those; a peer that stalls mid-message or goes silent is dropped and its slot
// freed; one too many is turned away and counted; imasim as a client calls again, with backoff,
// when the tracker's server drops it.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "devices/igtl_link.hpp"
#include "loopback_client.hpp"

namespace imasim::devices {
namespace {

using Client = test::LoopbackClient;

template <class Done>
bool poll_until(IgtlLink& link, ConsoleInput& input, Done done, double seconds = 5) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    link.poll(input);
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

IgtlLinkConfig any_port_server() {
  IgtlLinkConfig c;
  c.port = 0;
  return c;
}

Pose at_x(double x_m) {
  Pose p;
  p.translation = Vec3(Real(x_m), 0, 0);
  return p;
}

TEST(IgtlPeers, ATrackerForEachHandAndAPedalBoxAreFollowedAtOnce) {
  IgtlLink link(any_port_server());
  ConsoleInput input;
  const Client left(link.port()), right(link.port()), pedal(link.port());
  ASSERT_TRUE(poll_until(link, input, [&] { return link.peers_connected() == 3; }));
  // Each its own clock: the right tracker's an hour behind the left's, the pedal box unstamped.
  left.send(encode_pose("LeftHand", at_x(0.01), 3600.0));
  right.send(encode_pose("RightHand", at_x(0.02), 1.0));
  pedal.send(encode_values("Pedal", {1, 40}, 0.0));
  ASSERT_TRUE(poll_until(link, input, [&] {
    return input.left.has_pose && input.right.has_pose && input.pedal == haptics::CauteryMode::cut;
  }));
  EXPECT_NEAR(input.left.pose.translation.x(), 0.01, 1e-6);
  EXPECT_NEAR(input.right.pose.translation.x(), 0.02, 1e-6);
  EXPECT_EQ(input.power_w, 40);
  right.send(encode_pose("RightHand", at_x(0.03), 1.001));  // later on its own clock: followed
  ASSERT_TRUE(poll_until(link, input, [&] { return input.right.pose.translation.x() > 0.025; }));
  EXPECT_EQ(link.counters().refused_total(), 0u);
  EXPECT_TRUE(link.send_force(Hand::left, Vec3(0, 0, 1), 1.0));
  EXPECT_EQ(link.peers_seen(), 3u);
}

TEST(IgtlPeers, APedalBoxThatVanishesTakesThePedalOnlyWithIt) {
  IgtlLink link(any_port_server());
  ConsoleInput input;
  Client tracker(link.port()), pedal(link.port());
  tracker.send(encode_pose("LeftHand", at_x(0.01), 0.0));
  tracker.send(encode_pose("RightHand", at_x(0.02), 0.0));
  pedal.send(encode_values("Pedal", {1, 300}, 0.0));
  ASSERT_TRUE(poll_until(link, input, [&] {
    return input.right.has_pose && input.pedal == haptics::CauteryMode::cut;
  }));
  EXPECT_TRUE(link.part_connected(0) && link.part_connected(1) && link.part_connected(2));
  pedal.close();
  ASSERT_TRUE(poll_until(link, input, [&] { return !link.part_connected(2); }));
  EXPECT_TRUE(link.part_connected(0) && link.part_connected(1));
  EXPECT_TRUE(link.connected());
  // A pedal box back on a new connection drives the pedal again once it sends.
  const Client again(link.port());
  ASSERT_TRUE(poll_until(link, input, [&] { return link.peers_connected() == 2; }));
  EXPECT_FALSE(link.part_connected(2));
  again.send(encode_values("Pedal", {0}, 0.0));
  ASSERT_TRUE(poll_until(link, input, [&] { return link.part_connected(2); }));
  tracker.close();
  ASSERT_TRUE(poll_until(link, input, [&] { return !link.part_connected(0); }));
  EXPECT_FALSE(link.part_connected(1));
  EXPECT_TRUE(link.part_connected(2));
}

// A byte a second held the only connection slot: a message left unfinished for stall_timeout_s
// drops its peer, and the slot serves the next.
TEST(IgtlPeers, APeerStalledMidMessageIsDroppedAndCounted) {
  IgtlLinkConfig c = any_port_server();
  c.stall_timeout_s = 0.2;
  IgtlLink link(c);
  ConsoleInput input;
  const Client slow(link.port());
  const std::vector<std::uint8_t> pose = encode_pose("LeftHand", at_x(0.01), 0.0);
  slow.send(std::vector<std::uint8_t>(pose.begin(), pose.begin() + 10));
  const auto begun = std::chrono::steady_clock::now();
  ASSERT_TRUE(poll_until(link, input, [&] { return link.peers_timed_out() == 1; }));
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  EXPECT_GE(waited, 0.2);
  EXPECT_LT(waited, 1.0);
  EXPECT_FALSE(link.connected());
  EXPECT_TRUE(slow.closed_by_other_side());
  EXPECT_FALSE(input.left.has_pose);
}

// A program frozen with its socket open sends nothing: after idle_timeout_s it is dropped (and
// with it what it drove), while a peer that streams stays.
TEST(IgtlPeers, AnIdlePeerTimesOutWhileAStreamingOneStays) {
  IgtlLinkConfig c = any_port_server();
  c.idle_timeout_s = 0.3;
  IgtlLink link(c);
  ConsoleInput input;
  const Client frozen(link.port()), streaming(link.port());
  frozen.send(encode_values("Pedal", {1, 30}, 0.0));
  double t = 1.0;
  const auto begun = std::chrono::steady_clock::now();
  ASSERT_TRUE(poll_until(link, input, [&] {
    streaming.send(encode_pose("LeftHand", at_x(0.01), t += 0.001));
    return link.peers_timed_out() == 1;
  }));
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  EXPECT_GE(waited, 0.3);
  EXPECT_EQ(link.peers_connected(), 1u);
  EXPECT_FALSE(link.part_connected(2));
  EXPECT_TRUE(link.part_connected(0));
  EXPECT_TRUE(frozen.closed_by_other_side());
}

TEST(IgtlPeers, OneTooManyIsTurnedAwayAndCounted) {
  IgtlLink link(any_port_server());
  ConsoleInput input;
  std::vector<std::unique_ptr<Client>> clients;
  for (std::size_t k = 0; k < kIgtlMaxPeers; ++k)
    clients.push_back(std::make_unique<Client>(link.port()));
  ASSERT_TRUE(poll_until(link, input, [&] { return link.peers_connected() == kIgtlMaxPeers; }));
  const Client extra(link.port());
  ASSERT_TRUE(poll_until(link, input, [&] { return link.peers_turned_away() == 1; }));
  EXPECT_TRUE(extra.closed_by_other_side());
  EXPECT_EQ(link.peers_connected(), kIgtlMaxPeers);
}

// imasim as a client: the tracker's server drops the connection (a restarted PLUS server);
// imasim calls again, waiting longer after each call nobody answers, and follows the tracker
// with its clock restarted.
TEST(IgtlPeers, AClientCallsAgainWithBackoffAfterTheServerDropsIt) {
  const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(listener, 4), 0);
  socklen_t length = sizeof a;
  ::getsockname(listener, reinterpret_cast<sockaddr*>(&a), &length);
  IgtlLinkConfig c;
  c.role = IgtlLinkConfig::Role::client;
  c.port = ntohs(a.sin_port);
  c.reconnect_first_s = 0.05;
  c.reconnect_most_s = 0.2;
  IgtlLink link(c);
  ConsoleInput input;
  {
    const int first = ::accept(listener, nullptr, nullptr);
    const std::vector<std::uint8_t> m = encode_pose("LeftHand", at_x(0.01), 3600.0);
    ASSERT_EQ(::send(first, m.data(), m.size(), MSG_NOSIGNAL), ssize_t(m.size()));
    ASSERT_TRUE(poll_until(link, input, [&] { return input.left.has_pose; }));
    ::close(first);
  }
  ASSERT_TRUE(poll_until(link, input, [&] { return !link.connected(); }));
  // Called again within the first wait (and a little): the server answers at once.
  ASSERT_TRUE(poll_until(
      link, input, [&] { return link.reconnects() == 1; }, 1.0));
  const int second = ::accept(listener, nullptr, nullptr);
  const std::vector<std::uint8_t> m = encode_pose("LeftHand", at_x(0.04), 2.0);
  ASSERT_EQ(::send(second, m.data(), m.size(), MSG_NOSIGNAL), ssize_t(m.size()));
  ASSERT_TRUE(poll_until(link, input, [&] { return input.left.pose.translation.x() > 0.03; }));
  EXPECT_EQ(link.counters().refused_total(), 0u);
  // The server gone for good: calls go on, no faster than the longest wait, and never block.
  ::close(second);
  ::close(listener);
  const auto begun = std::chrono::steady_clock::now();
  int polls = 0;
  poll_until(
      link, input,
      [&] {
        ++polls;
        return false;
      },
      0.5);
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  EXPECT_LT(took, 0.7);
  EXPECT_GT(polls, 500);
  EXPECT_FALSE(link.connected());
  EXPECT_EQ(link.reconnects(), 1u);
  // Waits of 0.05, 0.1, 0.2, 0.2 ... s: at most 5 calls in 0.5 s, not one a poll.
  EXPECT_GE(link.calls_unanswered(), 2u);
  EXPECT_LE(link.calls_unanswered(), 5u);
}

}  // namespace
}  // namespace imasim::devices
