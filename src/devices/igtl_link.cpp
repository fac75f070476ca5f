#include "devices/igtl_link.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace imasim::devices {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw IgtlLinkError("OpenIGTLink: " + what +
                      (errno != 0 ? std::string(": ") + std::strerror(errno) : std::string()));
}

sockaddr_in socket_address(const std::string& address, std::uint16_t port) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  errno = 0;
  if (::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1)
    fail("'" + address + "' is not an IPv4 address");
  return a;
}

void make_non_blocking(int fd) {
  const int flags = ::fcntl(fd, F_GETFL, 0);
  ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
  const int one = 1;  // small messages at 1 kHz: no Nagle delay
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

// The link's own clock for its timeouts, monotonic whatever the loop's clock (unit: s).
double link_clock_s() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

bool is_loopback_address(const std::string& address) {
  in_addr a{};
  if (::inet_pton(AF_INET, address.c_str(), &a) != 1) return false;
  return (ntohl(a.s_addr) >> 24) == 127;
}

IgtlLink::IgtlLink(const IgtlLinkConfig& config) : config_(config), decoder_(config.names) {
  decoder_.set_tracker_to_scene(config.tracker_to_scene);
  errno = 0;
  if (!config.allow_remote && !is_loopback_address(config.address)) {
    fail("'" + config.address +
         "' is not a loopback address; name it in the scene file to allow a remote peer");
  }
  for (Peer& p : peers_) {
    p.buffer.reserve(kIgtlHeaderBytes + kIgtlMaxBodyBytes + kIgtlPollBytes);
    p.outgoing.reserve(kIgtlHeaderBytes + kIgtlMaxBodyBytes);
  }
  const sockaddr_in a = socket_address(config.address, config.port);
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) fail("socket");
  if (config.role == IgtlLinkConfig::Role::server) {
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0 ||
        ::listen(fd, int(kIgtlMaxPeers)) != 0) {
      const int e = errno;
      ::close(fd);
      errno = e;
      fail("cannot listen on " + config.address + ":" + std::to_string(config.port));
    }
    sockaddr_in bound{};
    socklen_t length = sizeof bound;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &length);
    port_ = ntohs(bound.sin_port);
    make_non_blocking(fd);
    listener_ = fd;
  } else {
    // The first call waits for its answer: nobody there at the start is an error the user sees.
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
      const int e = errno;
      ::close(fd);
      errno = e;
      fail("cannot connect to " + config.address + ":" + std::to_string(config.port));
    }
    port_ = config.port;
    open_peer(0, fd, link_clock_s());
  }
}

IgtlLink::~IgtlLink() {
  for (Peer& p : peers_)
    if (p.fd >= 0) ::close(p.fd);
  if (calling_ >= 0) ::close(calling_);
  if (listener_ >= 0) ::close(listener_);
}

bool IgtlLink::part_connected(std::size_t part) const {
  const PartSource& s = part_source_[std::min(part, part_source_.size() - 1)];
  if (s.slot == kIgtlMaxPeers) return connected();
  return peers_[s.slot].fd >= 0 && peers_[s.slot].serial == s.serial;
}

std::size_t IgtlLink::peers_connected() const {
  return std::size_t(
      std::count_if(peers_.begin(), peers_.end(), [](const Peer& p) { return p.fd >= 0; }));
}

void IgtlLink::open_peer(std::size_t slot, int fd, double now_s) {
  make_non_blocking(fd);
  Peer& p = peers_[slot];
  p.fd = fd;
  p.buffer.clear();
  p.outgoing.clear();
  p.last_message_s = now_s;
  p.partial_since_s = -1;
  p.serial = ++peers_seen_;
  decoder_.start_fresh(slot);  // ordering is per connection
}

void IgtlLink::drop_peer(Peer& p) {
  if (p.fd < 0) return;
  ::close(p.fd);
  p.fd = -1;
  p.buffer.clear();
  p.outgoing.clear();
  ++peers_dropped_;
  if (config_.role == IgtlLinkConfig::Role::client) {
    // Call again soon, then less often while nobody answers.
    call_wait_s_ = config_.reconnect_first_s;
    call_at_s_ = link_clock_s() + call_wait_s_;
  }
}

void IgtlLink::accept_waiting(double now_s) {
  for (;;) {
    const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) return;
    const auto free_slot =
        std::find_if(peers_.begin(), peers_.end(), [](const Peer& p) { return p.fd < 0; });
    if (free_slot == peers_.end()) {  // every slot taken: closed at once, and counted
      ::close(fd);
      ++peers_turned_away_;
      continue;
    }
    open_peer(std::size_t(free_slot - peers_.begin()), fd, now_s);
  }
}

void IgtlLink::call_again_if_due(double now_s) {
  if (peers_[0].fd >= 0) return;
  if (calling_ < 0) {
    if (now_s < call_at_s_) return;
    const sockaddr_in a = socket_address(config_.address, config_.port);
    calling_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    if (calling_ < 0) return;
    if (::connect(calling_, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) {
      open_peer(0, calling_, now_s);
      calling_ = -1;
      ++reconnects_;
      return;
    }
    if (errno != EINPROGRESS) {
      ::close(calling_);
      calling_ = -1;
      ++calls_unanswered_;
      call_wait_s_ = std::min(call_wait_s_ * 2, config_.reconnect_most_s);
      call_at_s_ = now_s + call_wait_s_;
      return;
    }
  }
  // A call under way: answered when the socket is writable.
  pollfd w{calling_, POLLOUT, 0};
  if (::poll(&w, 1, 0) <= 0) return;
  int error = 0;
  socklen_t length = sizeof error;
  ::getsockopt(calling_, SOL_SOCKET, SO_ERROR, &error, &length);
  if (error == 0) {
    open_peer(0, calling_, now_s);
    ++reconnects_;
  } else {
    ::close(calling_);
    ++calls_unanswered_;
    call_wait_s_ = std::min(call_wait_s_ * 2, config_.reconnect_most_s);
    call_at_s_ = now_s + call_wait_s_;
  }
  calling_ = -1;
}

int IgtlLink::poll(ConsoleInput& input, double now_s) {
  const double clock_s = link_clock_s();
  if (listener_ >= 0) accept_waiting(clock_s);
  if (config_.role == IgtlLinkConfig::Role::client) call_again_if_due(clock_s);
  int accepted = 0;
  for (std::size_t slot = 0; slot < peers_.size(); ++slot) {
    Peer& p = peers_[slot];
    if (p.fd < 0) continue;
    if (!flush_outgoing(p)) continue;  // the rest of a force the peer's socket had no room for
    if (!read_peer(slot, input, now_s, clock_s, accepted)) continue;
    const bool stalled =
        p.partial_since_s >= 0 && clock_s - p.partial_since_s > config_.stall_timeout_s;
    const bool idle =
        config_.idle_timeout_s > 0 && clock_s - p.last_message_s > config_.idle_timeout_s;
    if (stalled || idle) {
      drop_peer(p);
      ++peers_timed_out_;
    }
  }
  return accepted;
}

bool IgtlLink::read_peer(std::size_t slot, ConsoleInput& input, double arrival_s, double now_s,
                         int& accepted) {
  Peer& p = peers_[slot];
  std::uint8_t chunk[4096];
  bool whole_message = false;
  // At most kIgtlPollBytes a tick: a flood waits in the socket for the next ticks instead of
  // holding the 1 kHz loop (100 k refused messages at once held it 20-54 ms).
  for (std::size_t read = 0; read < kIgtlPollBytes;) {
    const ssize_t n = ::recv(p.fd, chunk, std::min(sizeof chunk, kIgtlPollBytes - read), 0);
    if (n == 0) {  // the peer closed
      drop_peer(p);
      return false;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) {
        drop_peer(p);
        return false;
      }
      break;
    }
    read += std::size_t(n);
    p.buffer.insert(p.buffer.end(), chunk, chunk + n);
    // Whole messages out of the buffer.
    std::size_t at = 0;
    while (p.buffer.size() - at >= kIgtlHeaderBytes) {
      const std::optional<IgtlHeader> h = decoder_.read_header(p.buffer.data() + at);
      if (!h) {  // not a header (or an oversized body): the stream cannot be followed
        drop_peer(p);
        return false;
      }
      const std::size_t whole = kIgtlHeaderBytes + std::size_t(h->body_bytes);
      if (p.buffer.size() - at < whole) break;
      if (decoder_.apply(p.buffer.data() + at, p.buffer.data() + at + kIgtlHeaderBytes,
                         std::size_t(h->body_bytes), input, arrival_s, slot)) {
        ++accepted;
        const int part = decoder_.last_part();
        if (part >= 0) part_source_[std::size_t(part)] = {slot, p.serial};
      }
      whole_message = true;
      at += whole;
    }
    p.buffer.erase(p.buffer.begin(), p.buffer.begin() + std::ptrdiff_t(at));
  }
  if (whole_message) {
    p.last_message_s = now_s;
    p.partial_since_s = p.buffer.empty() ? -1 : now_s;
  } else if (!p.buffer.empty() && p.partial_since_s < 0) {
    p.partial_since_s = now_s;
  }
  return true;
}

bool IgtlLink::flush_outgoing(Peer& p) {
  std::size_t sent = 0;
  while (p.fd >= 0 && sent < p.outgoing.size()) {
    const ssize_t n = ::send(p.fd, p.outgoing.data() + sent, p.outgoing.size() - sent,
                             MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;  // still full: later
    if (n <= 0) {
      drop_peer(p);
      return false;
    }
    sent += std::size_t(n);
  }
  p.outgoing.erase(p.outgoing.begin(), p.outgoing.begin() + std::ptrdiff_t(sent));
  return p.fd >= 0;
}

bool IgtlLink::send_to(Peer& p, const std::vector<std::uint8_t>& message) {
  if (p.fd < 0 || !flush_outgoing(p)) return false;
  // A peer that does not read forces (a tracker) fills its socket: the force is skipped, and
  // the peer is neither waited for nor dropped. A message is never cut: what did not fit of
  // the one begun is sent first.
  if (!p.outgoing.empty()) {
    ++forces_skipped_;
    return false;
  }
  std::size_t sent = 0;
  while (sent < message.size()) {
    const ssize_t n =
        ::send(p.fd, message.data() + sent, message.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    if (n <= 0) {
      drop_peer(p);
      return false;
    }
    sent += std::size_t(n);
  }
  if (sent == 0) {
    ++forces_skipped_;
    return false;
  }
  p.outgoing.insert(p.outgoing.end(), message.begin() + std::ptrdiff_t(sent), message.end());
  return true;
}

bool IgtlLink::send_force(Hand hand, const Vec3& force_n, double time_s) {
  if (!connected()) return false;
  const std::string& name =
      hand == Hand::left ? config_.names.left_force : config_.names.right_force;
  const std::vector<std::uint8_t> message = encode_force(name, force_n, time_s);
  bool taken = false;
  for (Peer& p : peers_)
    if (p.fd >= 0) taken = send_to(p, message) || taken;
  return taken;
}

}  // namespace imasim::devices
