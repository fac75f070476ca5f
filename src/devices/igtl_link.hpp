#pragma once
// OpenIGTLink over TCP: imasim as the server (trackers and devices connect to it, up to
// kIgtlMaxPeers at once: a tracker for each hand, a console and a pedal box) or as a client (it
// calls a tracker's server, and calls again with backoff when the connection is lost). Messages
// are read as they arrive, without blocking (the 1 kHz loop polls), checked and applied by
// IgtlDecoder, each connection with its own clock and order; forces leave as SENSOR messages to
// every peer. Loopback only unless the configuration allows a remote address (the scene file names
// one). A peer is dropped when it sends something that is not an OpenIGTLink header (the stream
// cannot be resynchronised), leaves a message unfinished for stall_timeout_s (a byte a second held
// the only slot), or sends nothing whole for idle_timeout_s (a program frozen with its socket
// open).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "devices/igtl_codec.hpp"

namespace imasim::devices {

struct IgtlLinkConfig {
  enum class Role : std::uint8_t { server, client };
  Role role = Role::server;
  std::string address = "127.0.0.1";  // server: where to listen; client: whom to call
  std::uint16_t port = 18944;         // the protocol's registered port; 0: any free (server)
  bool allow_remote = false;          // false: a non-loopback address is refused
  IgtlNames names;
  // A peer that sends no whole message this long is dropped; 0: never (unit: s). Trackers stream
  // continuously (PLUS, Slicer's OpenIGTLinkIF at 10-100 Hz).
  double idle_timeout_s = 5;
  double stall_timeout_s = 1;  // a message begun and not finished this long: dropped (unit: s)
  Pose tracker_to_scene;  // the tracker's frame in the scene (IgtlDecoder::set_tracker_to_scene)
  // Client: the wait before calling again after a lost connection, doubling from the first to
  // the second on each failed call (unit: s).
  double reconnect_first_s = 0.1, reconnect_most_s = 2;
};

// What one poll reads from the socket at most: 16 KiB a millisecond is 16 MB/s, hundreds of times
// what two hands, their buttons and a pedal send at 1 kHz (unit: bytes).
inline constexpr std::size_t kIgtlPollBytes = 16 << 10;

class IgtlLinkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class IgtlLink {
 public:
  // Listens or connects; throws IgtlLinkError (address refused, port taken, nobody there).
  explicit IgtlLink(const IgtlLinkConfig& config);
  ~IgtlLink();
  IgtlLink(const IgtlLink&) = delete;
  IgtlLink& operator=(const IgtlLink&) = delete;

  // Accepts waiting peers (server) or calls again when due (client), reads what has arrived from
  // each peer, up to kIgtlPollBytes a peer (the rest waits for the next poll), and applies each
  // whole message to `input`, unstamped ones timed `now_s` (the loop's clock). Drops peers that
  // stalled or went idle. Never blocks. Returns the messages accepted.
  int poll(ConsoleInput& input, double now_s = 0);

  // Sends the force on one hand to every peer; false when none took it: no peer is connected, or
  // each is gone or has a full socket (a peer that does not read forces): the force is then
  // skipped for it and counted, and the peer kept. Never blocks.
  bool send_force(Hand hand, const Vec3& force_n, double time_s);

  bool connected() const { return peers_connected() > 0; }
  // Part 0 left hand, 1 right hand, 2 pedal: whether the connection that last drove it is still
  // up (before any drove it: whether any peer is). A part's peer that vanishes loses the part,
  // whatever other peers stay.
  bool part_connected(std::size_t part) const;
  std::size_t peers_connected() const;
  std::uint16_t port() const { return port_; }  // the port listened on (server)
  const IgtlCounters& counters() const { return decoder_.counters(); }
  std::uint64_t peers_dropped() const { return peers_dropped_; }      // for any reason, all told
  std::uint64_t peers_seen() const { return peers_seen_; }            // connections made, all told
  std::uint64_t peers_timed_out() const { return peers_timed_out_; }  // stalled or idle
  // Connections closed at once because kIgtlMaxPeers were connected.
  std::uint64_t peers_turned_away() const { return peers_turned_away_; }
  std::uint64_t reconnects() const { return reconnects_; }  // a client's calls again that took
  std::uint64_t calls_unanswered() const { return calls_unanswered_; }  // and those that did not
  std::uint64_t forces_skipped() const { return forces_skipped_; }      // for a full socket

 private:
  struct Peer {
    int fd = -1;
    std::vector<std::uint8_t> buffer;    // what arrived and is not yet a whole message
    std::vector<std::uint8_t> outgoing;  // the unsent rest of the last force message
    double last_message_s = 0;           // when its last whole message arrived (link clock)
    double partial_since_s = -1;         // when its unfinished message began; < 0: none
    std::uint64_t serial = 0;            // which connection of the slot (one more for each)
  };
  struct PartSource {
    std::size_t slot = kIgtlMaxPeers;  // kIgtlMaxPeers: no peer has driven it
    std::uint64_t serial = 0;
  };

  void open_peer(std::size_t slot, int fd, double now_s);
  void drop_peer(Peer& p);
  void accept_waiting(double now_s);
  void call_again_if_due(double now_s);
  // Reads and applies what `p` sent; false when it was dropped.
  bool read_peer(std::size_t slot, ConsoleInput& input, double arrival_s, double now_s, int& n);
  // Sends what it can of `p.outgoing`; false when the peer is gone (and dropped).
  bool flush_outgoing(Peer& p);
  bool send_to(Peer& p, const std::vector<std::uint8_t>& message);

  IgtlLinkConfig config_;
  IgtlDecoder decoder_;
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::array<Peer, kIgtlMaxPeers> peers_;
  std::array<PartSource, 3> part_source_{};
  // Client: a call under way (non-blocking connect), and when to call next (link clock, unit: s).
  int calling_ = -1;
  double call_at_s_ = 0, call_wait_s_ = 0;
  std::uint64_t peers_dropped_ = 0, peers_seen_ = 0, peers_timed_out_ = 0, peers_turned_away_ = 0;
  std::uint64_t reconnects_ = 0, calls_unanswered_ = 0, forces_skipped_ = 0;
};

// Whether `address` (dotted IPv4) is a loopback address (127.0.0.0/8).
bool is_loopback_address(const std::string& address);

}  // namespace imasim::devices
