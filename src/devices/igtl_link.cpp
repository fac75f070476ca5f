#include "devices/igtl_link.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
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

}  // namespace

bool is_loopback_address(const std::string& address) {
  in_addr a{};
  if (::inet_pton(AF_INET, address.c_str(), &a) != 1) return false;
  return (ntohl(a.s_addr) >> 24) == 127;
}

IgtlLink::IgtlLink(const IgtlLinkConfig& config) : config_(config), decoder_(config.names) {
  errno = 0;
  if (!config.allow_remote && !is_loopback_address(config.address)) {
    fail("'" + config.address +
         "' is not a loopback address; name it in the scene file to allow a remote peer");
  }
  const sockaddr_in a = socket_address(config.address, config.port);
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) fail("socket");
  if (config.role == IgtlLinkConfig::Role::server) {
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 1) != 0) {
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
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
      const int e = errno;
      ::close(fd);
      errno = e;
      fail("cannot connect to " + config.address + ":" + std::to_string(config.port));
    }
    port_ = config.port;
    make_non_blocking(fd);
    peer_ = fd;
    ++peers_seen_;
  }
  buffer_.reserve(kIgtlHeaderBytes + kIgtlMaxBodyBytes + kIgtlPollBytes);
  outgoing_.reserve(kIgtlHeaderBytes + kIgtlMaxBodyBytes);
}

IgtlLink::~IgtlLink() {
  if (peer_ >= 0) ::close(peer_);
  if (listener_ >= 0) ::close(listener_);
}

void IgtlLink::drop_peer() {
  if (peer_ >= 0) ::close(peer_);
  peer_ = -1;
  buffer_.clear();
  outgoing_.clear();
  ++peers_dropped_;
}

int IgtlLink::poll(ConsoleInput& input, double now_s) {
  if (peer_ < 0 && listener_ >= 0) {
    const int fd = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd >= 0) {
      make_non_blocking(fd);
      peer_ = fd;
      ++peers_seen_;
      decoder_.start_fresh();  // ordering is per connection
    }
  }
  if (peer_ < 0) return 0;
  flush_outgoing();  // the rest of a force the peer's socket had no room for
  if (peer_ < 0) return 0;
  int accepted = 0;
  std::uint8_t chunk[4096];
  // At most kIgtlPollBytes a tick: a flood waits in the socket for the next ticks instead of
  // holding the 1 kHz loop (100 k refused messages at once held it 20-54 ms).
  for (std::size_t read = 0; read < kIgtlPollBytes;) {
    const ssize_t n = ::recv(peer_, chunk, std::min(sizeof chunk, kIgtlPollBytes - read), 0);
    if (n == 0) {  // the peer closed
      drop_peer();
      return accepted;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) drop_peer();
      return accepted;
    }
    read += std::size_t(n);
    buffer_.insert(buffer_.end(), chunk, chunk + n);
    // Whole messages out of the buffer.
    std::size_t at = 0;
    while (buffer_.size() - at >= kIgtlHeaderBytes) {
      const std::optional<IgtlHeader> h = decoder_.read_header(buffer_.data() + at);
      if (!h) {  // not a header (or an oversized body): the stream cannot be followed
        drop_peer();
        return accepted;
      }
      const std::size_t whole = kIgtlHeaderBytes + std::size_t(h->body_bytes);
      if (buffer_.size() - at < whole) break;
      if (decoder_.apply(buffer_.data() + at, buffer_.data() + at + kIgtlHeaderBytes,
                         std::size_t(h->body_bytes), input, now_s)) {
        ++accepted;
      }
      at += whole;
    }
    buffer_.erase(buffer_.begin(), buffer_.begin() + std::ptrdiff_t(at));
  }
  return accepted;
}

bool IgtlLink::flush_outgoing() {
  std::size_t sent = 0;
  while (peer_ >= 0 && sent < outgoing_.size()) {
    const ssize_t n = ::send(peer_, outgoing_.data() + sent, outgoing_.size() - sent,
                             MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;  // still full: later
    if (n <= 0) {
      drop_peer();
      return false;
    }
    sent += std::size_t(n);
  }
  outgoing_.erase(outgoing_.begin(), outgoing_.begin() + std::ptrdiff_t(sent));
  return peer_ >= 0;
}

bool IgtlLink::send_force(Hand hand, const Vec3& force_n, double time_s) {
  if (peer_ < 0 || !flush_outgoing()) return false;
  // A peer that does not read forces (a tracker) fills its socket: the force is skipped, and
  // the peer is neither waited for nor dropped. A message is never cut: what did not fit of
  // the one begun is sent first.
  if (!outgoing_.empty()) {
    ++forces_skipped_;
    return false;
  }
  const std::string& name =
      hand == Hand::left ? config_.names.left_force : config_.names.right_force;
  const std::vector<std::uint8_t> message = encode_force(name, force_n, time_s);
  std::size_t sent = 0;
  while (sent < message.size()) {
    const ssize_t n =
        ::send(peer_, message.data() + sent, message.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    if (n <= 0) {
      drop_peer();
      return false;
    }
    sent += std::size_t(n);
  }
  if (sent == 0) {
    ++forces_skipped_;
    return false;
  }
  outgoing_.insert(outgoing_.end(), message.begin() + std::ptrdiff_t(sent), message.end());
  return true;
}

}  // namespace imasim::devices
