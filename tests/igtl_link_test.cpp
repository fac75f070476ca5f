// OpenIGTLink over loopback TCP: a device connects, streams hand poses and buttons, and gets back
// the force of eq. 17 for where its hand is; imasim can also call a tracker's server; remote
// addresses are refused unless allowed; a peer sending garbage is dropped and the next one served.
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "devices/igtl_link.hpp"
#include "haptics/local_model.hpp"

namespace imasim::devices {
namespace {

// A plain TCP client or accepted connection, as another program would be.
class Peer {
 public:
  explicit Peer(int fd) : fd_(fd) {}
  ~Peer() {
    if (fd_ >= 0) ::close(fd_);
  }
  static Peer connect_to(std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    EXPECT_EQ(::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a), 0);
    return Peer(fd);
  }
  Peer(Peer&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  void send(const std::vector<std::uint8_t>& bytes) const {
    ASSERT_EQ(::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL), ssize_t(bytes.size()));
  }
  // One whole message (blocking, with a 5 s limit).
  std::vector<std::uint8_t> receive_message() const {
    timeval limit{5, 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
    std::vector<std::uint8_t> m(kIgtlHeaderBytes);
    if (::recv(fd_, m.data(), m.size(), MSG_WAITALL) != ssize_t(m.size())) return {};
    IgtlDecoder d;
    const std::optional<IgtlHeader> h = d.read_header(m.data());
    if (!h) return {};
    m.resize(kIgtlHeaderBytes + h->body_bytes);
    if (h->body_bytes > 0 && ::recv(fd_, m.data() + kIgtlHeaderBytes, h->body_bytes, MSG_WAITALL) !=
                                 ssize_t(h->body_bytes)) {
      return {};
    }
    return m;
  }

 private:
  int fd_;
};

// Polls until `done` or 5 s.
template <class Done>
void poll_until(IgtlLink& link, ConsoleInput& input, Done done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!done() && std::chrono::steady_clock::now() < end) {
    link.poll(input);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

IgtlLinkConfig any_port_server() {
  IgtlLinkConfig c;
  c.port = 0;
  return c;
}

TEST(IgtlLink, ADevicePressingIntoTissueGetsTheForceOfEquation17) {
  IgtlLink link(any_port_server());
  ASSERT_GT(link.port(), 0);
  const Peer device = Peer::connect_to(link.port());
  // The local model: fascia whose surface is the plane z = 10 mm, normal +z.
  haptics::LocalModel model;
  model.contact_count = 1;
  model.contacts[0].point = Vec3(0, 0, 0.01);
  model.contacts[0].normal = Vec3::UnitZ();
  model.contacts[0].tissue = haptics::TissueKind::fascia;
  const haptics::ForceModelParams params = haptics::default_force_model_params();
  ConsoleInput input;
  for (int k = 1; k <= 5; ++k) {
    // The hand 1, 2, ... 5 mm into the tissue (sent in millimetres), still.
    Pose hand;
    hand.translation = Vec3(0, 0, 0.01 - 0.001 * k);
    device.send(encode_pose("LeftHand", hand, 0.001 * k));
    poll_until(link, input, [&] { return input.left.time_s >= 0.001 * k - 1e-9; });
    ASSERT_TRUE(input.left.has_pose);
    haptics::DeviceTip tip;
    tip.position = input.left.pose.translation;
    const haptics::ForceChannels f = haptics::evaluate_local_model(model, params, tip, 0);
    ASSERT_TRUE(link.send_force(Hand::left, f.total(), input.left.time_s));
    const std::vector<std::uint8_t> reply = device.receive_message();
    ASSERT_FALSE(reply.empty());
    const std::optional<std::vector<double>> force = decode_sensor(
        reply.data(), reply.data() + kIgtlHeaderBytes, reply.size() - kIgtlHeaderBytes);
    ASSERT_TRUE(force && force->size() == 3);
    // eq. 17 by hand: k_d d (the tip is evaluated at rest, so the damping term is zero).
    const double expected = params.of(haptics::TissueKind::fascia).stiffness * 0.001 * k;
    EXPECT_NEAR((*force)[2], expected, 1e-4) << k;  // poses travel as float millimetres
    EXPECT_EQ((*force)[0], 0);
  }
  // Buttons and the pedal over the same connection.
  device.send(encode_values("LeftButtons", {1, 0.25}, 1.0));
  device.send(encode_values("Pedal", {1}, 1.0));
  poll_until(link, input, [&] { return input.pedal == haptics::CauteryMode::cut; });
  EXPECT_TRUE(input.left.clutch);
  EXPECT_EQ(input.left.jaw, Real(0.25));
  EXPECT_EQ(link.counters().accepted, 7u);
  EXPECT_EQ(link.counters().refused_total(), 0u);
}

TEST(IgtlLink, APeerSendingGarbageIsDroppedAndTheNextIsServed) {
  IgtlLink link(any_port_server());
  ConsoleInput input;
  {
    const Peer bad = Peer::connect_to(link.port());
    bad.send(std::vector<std::uint8_t>(200, 0x5a));
    poll_until(link, input, [&] { return link.peers_dropped() > 0; });
  }
  EXPECT_EQ(link.peers_dropped(), 1u);
  EXPECT_FALSE(link.connected());
  const Peer good = Peer::connect_to(link.port());
  Pose hand;
  hand.translation = Vec3(0.001, 0.002, 0.003);
  good.send(encode_pose("RightHand", hand, 2.0));
  poll_until(link, input, [&] { return input.right.has_pose; });
  EXPECT_TRUE(input.right.pose.translation.isApprox(hand.translation, 1e-6));
}

// 100 k refused messages at once held the 1 kHz loop 20-54 ms: poll read the whole socket. It
// reads at most kIgtlPollBytes a tick now; the rest waits in the socket for the next ticks.
TEST(IgtlLink, AFloodIsReadABoundedAmountAPoll) {
  IgtlLink link(any_port_server());
  const Peer flood = Peer::connect_to(link.port());
  ConsoleInput input;
  poll_until(link, input, [&] { return link.connected(); });
  const std::vector<std::uint8_t> one = encode_pose("Stranger", Pose{}, 1.0);
  constexpr int kMessages = 600;  // 64 KB: within the socket's buffer
  std::vector<std::uint8_t> all;
  for (int k = 0; k < kMessages; ++k)
    all.insert(all.end(), one.begin(), one.end());
  flood.send(all);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // all of it in the socket
  link.poll(input, 1.0);
  const std::uint64_t first = link.counters().refused_total();
  EXPECT_GT(first, 0u);
  EXPECT_LE(first, kIgtlPollBytes / one.size());
  int polls = 1;
  poll_until(link, input, [&] {
    ++polls;
    return link.counters().refused_total() == std::uint64_t(kMessages);
  });
  EXPECT_EQ(link.counters().refused_total(), std::uint64_t(kMessages));
  EXPECT_GE(polls, int(all.size() / kIgtlPollBytes));
  EXPECT_TRUE(link.connected());
}

// A tracking-only peer never reads the forces sent back: its socket fills. The force is then
// skipped and counted, the peer kept and still followed (it was dropped, and with it the
// tracker), and no message is ever cut in two.
TEST(IgtlLink, APeerThatReadsNoForcesKeepsItsConnection) {
  IgtlLink link(any_port_server());
  const Peer tracker = Peer::connect_to(link.port());
  ConsoleInput input;
  poll_until(link, input, [&] { return link.connected(); });
  int sent = 0;
  for (int k = 0; k < 1'000'000 && link.forces_skipped() < 10; ++k)
    sent += link.send_force(Hand::left, Vec3(0, 0, 0.5), 0.001 * k) ? 1 : 0;
  ASSERT_EQ(link.forces_skipped(), 10u);
  EXPECT_TRUE(link.connected());
  EXPECT_EQ(link.peers_dropped(), 0u);
  Pose hand;
  hand.translation = Vec3(0.001, 0, 0);
  tracker.send(encode_pose("LeftHand", hand, 5.0));
  poll_until(link, input, [&] { return input.left.has_pose; });
  EXPECT_TRUE(input.left.pose.translation.isApprox(hand.translation, 1e-6));
  // Every message that left is whole: the tracker reads each one back as a force.
  for (int k = 0; k < sent; ++k) {
    if (k % 64 == 0) link.poll(input, 0);  // the rest of a message begun goes out
    const std::vector<std::uint8_t> m = tracker.receive_message();
    ASSERT_FALSE(m.empty()) << k << " of " << sent;
    const auto force =
        decode_sensor(m.data(), m.data() + kIgtlHeaderBytes, m.size() - kIgtlHeaderBytes);
    ASSERT_TRUE(force && force->size() == 3u) << k;
    EXPECT_EQ((*force)[2], 0.5);
  }
  EXPECT_TRUE(link.send_force(Hand::left, Vec3::Zero(), 10.0));  // room again
}

TEST(IgtlLink, ImasimCanCallATrackersServer) {
  // A tracker's server on an ephemeral loopback port.
  const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
  ASSERT_EQ(::bind(listener, reinterpret_cast<const sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(listener, 1), 0);
  socklen_t length = sizeof a;
  ::getsockname(listener, reinterpret_cast<sockaddr*>(&a), &length);
  IgtlLinkConfig c;
  c.role = IgtlLinkConfig::Role::client;
  c.port = ntohs(a.sin_port);
  IgtlLink link(c);
  const Peer tracker(::accept(listener, nullptr, nullptr));
  ::close(listener);
  Pose hand;
  hand.translation = Vec3(0.02, 0, 0);
  tracker.send(encode_pose("LeftHand", hand, 3.0));
  ConsoleInput input;
  poll_until(link, input, [&] { return input.left.has_pose; });
  EXPECT_TRUE(input.left.pose.translation.isApprox(hand.translation, 1e-6));
  EXPECT_TRUE(link.send_force(Hand::right, Vec3(0, 1, 0), 3.0));
  EXPECT_FALSE(tracker.receive_message().empty());
}

TEST(IgtlLink, RemoteAddressesAreRefusedUnlessAllowed) {
  IgtlLinkConfig c;
  c.address = "10.1.2.3";
  try {
    IgtlLink link(c);
    ADD_FAILURE() << "listened on a remote address";
  } catch (const IgtlLinkError& e) {
    EXPECT_NE(std::string(e.what()).find("'10.1.2.3' is not a loopback address"), std::string::npos)
        << e.what();
  }
  c.address = "not an address";
  EXPECT_THROW(IgtlLink link(c), IgtlLinkError);
  EXPECT_TRUE(is_loopback_address("127.0.0.1"));
  EXPECT_TRUE(is_loopback_address("127.4.5.6"));
  EXPECT_FALSE(is_loopback_address("128.0.0.1"));
  // Nobody listening: a clear error, not a hang.
  IgtlLinkConfig client;
  client.role = IgtlLinkConfig::Role::client;
  client.port = 1;
  EXPECT_THROW(IgtlLink link(client), IgtlLinkError);
}

}  // namespace
}  // namespace imasim::devices
