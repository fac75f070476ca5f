#include "devices/emulated_console.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace imasim::devices {

void EmulatedHand::step(const EmulatedHandParams& p, const Vec3& target, const Vec3& force,
                        Real dt) {
  Vec3 f = force;
  const Real magnitude = f.norm();
  if (!(magnitude <= p.max_force_n))
    f = magnitude > 0 ? Vec3(f * (p.max_force_n / magnitude)) : Vec3::Zero();
  const Vec3 a = (p.stiffness * (target - x) - p.damping * v + f) / p.mass;
  v += dt * a;
  x += dt * v;
}

EmulatedConsole::EmulatedConsole(const std::string& address, std::uint16_t port, double wait_s,
                                 EmulatedHandParams params, IgtlNames names)
    : params_(params), names_(std::move(names)) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  if (::inet_pton(AF_INET, address.c_str(), &a.sin_addr) != 1)
    throw std::runtime_error("device emulator: '" + address + "' is not an IPv4 address");
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(wait_s);
  for (;;) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd_ >= 0 && ::connect(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0) break;
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (std::chrono::steady_clock::now() > until) {
      throw std::runtime_error("device emulator: nobody answers at " + address + ":" +
                               std::to_string(port));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

EmulatedConsole::~EmulatedConsole() {
  if (fd_ >= 0) ::close(fd_);
}

bool EmulatedConsole::send(const std::vector<std::uint8_t>& m) {
  return ::send(fd_, m.data(), m.size(), MSG_NOSIGNAL) == ssize_t(m.size());
}

bool EmulatedConsole::read_forces() {
  std::uint8_t chunk[4096];
  for (;;) {
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT);
    if (n == 0) return false;  // imasim closed the connection
    if (n < 0) break;          // nothing more now
    in_.insert(in_.end(), chunk, chunk + n);
  }
  std::size_t at = 0;
  IgtlDecoder reader;
  while (in_.size() - at >= kIgtlHeaderBytes) {
    const std::optional<IgtlHeader> h = reader.read_header(in_.data() + at);
    if (!h) return false;  // not OpenIGTLink: the stream cannot be resynchronised
    const std::size_t whole = kIgtlHeaderBytes + std::size_t(h->body_bytes);
    if (in_.size() - at < whole) break;
    const auto f = decode_sensor(in_.data() + at, in_.data() + at + kIgtlHeaderBytes,
                                 std::size_t(h->body_bytes));
    const bool left = h->device == names_.left_force, right = h->device == names_.right_force;
    if (f && f->size() == 3 && (left || right)) {
      const Vec3 force{Real((*f)[0]), Real((*f)[1]), Real((*f)[2])};
      if (force.allFinite()) {
        force_[left ? 0 : 1] = force;
        ++forces_received_;
      }
    }
    at += whole;
  }
  in_.erase(in_.begin(), in_.begin() + std::ptrdiff_t(at));
  return true;
}

bool EmulatedConsole::tick(double t, const EmulatorTarget& target) {
  if (!read_forces()) return false;
  constexpr Real kTick = Real(1e-3);
  for (int h = 0; h < 2; ++h) {
    if (!target.has_pose[h]) continue;
    EmulatedHand& hand = hands_[h];
    if (!hand.placed || target.frame[h] != last_sent_.frame[h]) {
      hand.x = target.pose[h].translation;  // picked up at the path's start
      hand.v.setZero();
      hand.placed = true;
    }
    hand.step(params_, target.pose[h].translation, force_[h], kTick);
    Pose p = target.pose[h];
    p.translation = hand.x;
    const bool tool = target.frame[h] == PoseFrame::tool;
    const std::string& name = h == 0 ? (tool ? names_.left_tool : names_.left_pose)
                                     : (tool ? names_.right_tool : names_.right_pose);
    if (!send(encode_pose(name, p, t))) return false;
  }
  const bool changed = target.clutch != last_sent_.clutch || target.jaw != last_sent_.jaw ||
                       target.pedal != last_sent_.pedal || target.power_w != last_sent_.power_w;
  if (changed || ticks_ % 10 == 0) {
    for (int h = 0; h < 2; ++h) {
      if (!send(encode_values(h == 0 ? names_.left_buttons : names_.right_buttons,
                              {target.clutch[h] ? 1.0 : 0.0, double(target.jaw[h])}, t)))
        return false;
    }
    if (!send(encode_values(names_.pedal, {double(int(target.pedal)), double(target.power_w)}, t)))
      return false;
  }
  last_sent_ = target;
  ++ticks_;
  return true;
}

}  // namespace imasim::devices
