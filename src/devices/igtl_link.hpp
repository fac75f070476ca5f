#pragma once
// One OpenIGTLink connection over TCP (issue 13): imasim as the server (trackers and devices
// connect to it) or as a client (it connects to a tracker's server). Messages are read as they
// arrive, without blocking (the 1 kHz loop polls), checked and applied by IgtlDecoder; forces
// leave as SENSOR messages. Loopback only unless the configuration allows a remote address (the
// scene file names one). A peer that sends something that is not an OpenIGTLink header is
// dropped (the stream cannot be resynchronised); a server then waits for the next peer.
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

  // Accepts a waiting peer (server), reads what has arrived, up to kIgtlPollBytes (the rest waits
  // for the next poll), and applies each whole message to `input`, unstamped ones timed `now_s`
  // (the loop's clock). Never blocks. Returns the messages accepted.
  int poll(ConsoleInput& input, double now_s = 0);

  // Sends the force on one hand; false when no peer is connected, the peer is gone, or its
  // socket is full (a peer that does not read forces): the force is then skipped and counted,
  // and the peer kept. Never blocks.
  bool send_force(Hand hand, const Vec3& force_n, double time_s);

  bool connected() const { return peer_ >= 0; }
  std::uint16_t port() const { return port_; }  // the port listened on (server)
  const IgtlCounters& counters() const { return decoder_.counters(); }
  std::uint64_t peers_dropped() const { return peers_dropped_; }
  std::uint64_t peers_seen() const { return peers_seen_; }          // connections made, all told
  std::uint64_t forces_skipped() const { return forces_skipped_; }  // for a full socket

 private:
  void drop_peer();
  // Sends what it can of `outgoing_`; false when the peer is gone (and dropped).
  bool flush_outgoing();

  IgtlLinkConfig config_;
  IgtlDecoder decoder_;
  int listener_ = -1, peer_ = -1;
  std::uint16_t port_ = 0;
  std::vector<std::uint8_t> buffer_;
  std::vector<std::uint8_t> outgoing_;  // the unsent rest of the last force message
  std::uint64_t peers_dropped_ = 0, peers_seen_ = 0, forces_skipped_ = 0;
};

// Whether `address` (dotted IPv4) is a loopback address (127.0.0.0/8).
bool is_loopback_address(const std::string& address);

}  // namespace imasim::devices
