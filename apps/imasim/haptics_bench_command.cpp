#include "haptics_bench_command.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_checks.hpp"
#include "devices/igtl_link.hpp"
#include "haptics/force_safety.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/latest_value.hpp"
#include "haptics/local_model.hpp"
#include "interrupt.hpp"
#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

namespace {

using Clock = std::chrono::steady_clock;
using Models = std::array<haptics::LocalModel, 2>;
using Tips = std::array<Vec3, 2>;

constexpr double kStep = 0.005;  // the physics step (unit: s)

haptics::TissueKind tissue_kind(surgery::Tissue t) {
  switch (t) {
    case surgery::Tissue::fat:
      return haptics::TissueKind::fat;
    case surgery::Tissue::ima:
      return haptics::TissueKind::ima;
    case surgery::Tissue::heart:
      return haptics::TissueKind::heart;
    case surgery::Tissue::chest_wall:
      return haptics::TissueKind::chest_wall;
    default:
      return haptics::TissueKind::fascia;
  }
}

// The instrument's tip: the hinge plus the jaw length along the shaft (f = R (0, 0, 1)).
Vec3 tool_tip(const session::Station& s) {
  return s.pose.apply(Vec3(0, 0, s.instrument.jaws.length));
}

// What the haptic loop needs of one instrument after a physics step: its deepest contact (the
// tool's outward normal there is the way the tissue pushes back, reversed), the tissue, the
// cautery.
haptics::LocalModel local_model(const session::SurgicalSession& s, int station, double time,
                                std::uint64_t step) {
  const session::Station& st = s.stations[std::size_t(station)];
  haptics::LocalModel m;
  m.time_s = time;
  m.step = step;
  if (st.contact.count > 0) {
    surgery::Tissue tissue = surgery::Tissue::fascia;
    for (std::size_t k = 0; k < 8 && k < s.object_tissue.size(); ++k)
      if (st.contact.per_object[k] > 0) tissue = s.object_tissue[k];
    m.contact_count = 1;
    m.contacts[0].point = st.contact.point;
    m.contacts[0].normal = -st.contact.normal;
    m.contacts[0].tissue = tissue_kind(tissue);
  }
  if (station == 1 && st.pedal != surgery::PedalMode::off) {
    m.cautery = st.pedal == surgery::PedalMode::cut ? haptics::CauteryMode::cut
                                                    : haptics::CauteryMode::coag;
    m.power_w = s.params.cautery.power;
  }
  return m;
}

// Two emulated desktop devices (mass 0.1 kg, a 200 N/m spring and 4 N s/m damper pulling each
// toward its instrument's tip) stepped at 1 kHz, sending poses and applying received forces.
class EmulatedDevices {
 public:
  EmulatedDevices(std::uint16_t port, haptics::LatestValue<Tips>& tips) : tips_(tips) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    ::inet_pton(AF_INET, "127.0.0.1", &a.sin_addr);
    if (::connect(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0)
      throw std::runtime_error("the emulated devices cannot connect");
    const int one = 1;
    ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    timeval wait{0, 200};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    thread_ = std::thread([this] { run(); });
  }
  ~EmulatedDevices() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    ::close(fd_);
  }

 private:
  void run() {
    const char* names[2] = {"LeftHand", "RightHand"};
    Tips target{Vec3::Zero(), Vec3::Zero()};
    std::array<Vec3, 2> x{Vec3::Zero(), Vec3::Zero()}, v{Vec3::Zero(), Vec3::Zero()},
        force{Vec3::Zero(), Vec3::Zero()};
    bool placed = false;
    const auto start = Clock::now();
    auto next = start;
    std::vector<std::uint8_t> in;
    while (!stop_) {
      next += std::chrono::milliseconds(1);
      std::this_thread::sleep_until(next);
      const double t = std::chrono::duration<double>(Clock::now() - start).count();
      if (tips_.read(target) && !placed) {
        x = target;
        placed = true;
      }
      if (!placed) continue;
      for (int h = 0; h < 2; ++h) {
        const Vec3 a = (Real(200) * (target[h] - x[h]) - Real(4) * v[h] + force[h]) / Real(0.1);
        v[h] += Real(1e-3) * a;
        x[h] += Real(1e-3) * v[h];
        Pose p;
        p.translation = x[h];
        const std::vector<std::uint8_t> m = devices::encode_pose(names[h], p, t);
        if (::send(fd_, m.data(), m.size(), MSG_NOSIGNAL) != ssize_t(m.size())) return;
      }
      // Forces that arrived (SENSOR LeftForce / RightForce).
      std::uint8_t chunk[4096];
      const ssize_t n = ::recv(fd_, chunk, sizeof chunk, MSG_DONTWAIT);
      if (n > 0) in.insert(in.end(), chunk, chunk + n);
      std::size_t at = 0;
      devices::IgtlDecoder reader;
      while (in.size() - at >= devices::kIgtlHeaderBytes) {
        const std::optional<devices::IgtlHeader> hd = reader.read_header(in.data() + at);
        if (!hd) return;
        const std::size_t whole = devices::kIgtlHeaderBytes + std::size_t(hd->body_bytes);
        if (in.size() - at < whole) break;
        const auto f =
            devices::decode_sensor(in.data() + at, in.data() + at + devices::kIgtlHeaderBytes,
                                   std::size_t(hd->body_bytes));
        if (f && f->size() == 3)
          force[hd->device == "LeftForce" ? 0 : 1] = Vec3((*f)[0], (*f)[1], (*f)[2]);
        at += whole;
      }
      in.erase(in.begin(), in.begin() + std::ptrdiff_t(at));
    }
  }

  haptics::LatestValue<Tips>& tips_;
  int fd_ = -1;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace

std::shared_ptr<HapticsBenchOptions> add_haptics_bench_command(CLI::App& app) {
  auto opt = std::make_shared<HapticsBenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "haptics-bench", "Measure the 1 kHz haptic loop while the default scene runs in real time");
  cmd->add_option("--seconds", opt->seconds, "Wall-clock seconds to run")
      ->capture_default_str()
      ->check(finite_range(0.1, 3600));
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_haptics_bench_command(const HapticsBenchOptions& o) {
  const surgery::InputScript script =
      surgery::load_input_script(std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script");
  session::SurgicalSession s = session::make_surgical_session(scene::default_thorax_scene_params(),
                                                              session::SessionParams{});
  physics::Executor exec(1);  // physics on one core, haptics and the devices on the other

  devices::IgtlLinkConfig link_config;
  link_config.port = 0;
  devices::IgtlLink link(link_config);
  haptics::LatestValue<Models> models;
  haptics::LatestValue<Tips> tips;
  const haptics::ForceModelParams params = haptics::default_force_model_params();
  const Clock::time_point t0 = Clock::now();
  auto now_s = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  std::array<haptics::ForceSafety, 2> safety{haptics::ForceSafety({}, 0.0),
                                             haptics::ForceSafety({}, 0.0)};
  devices::ConsoleInput input;
  Models latest{};
  double force_max = 0;
  std::uint64_t contacts = 0, last_step_seen = 0;
  haptics::HapticLoop loop({}, [&](double) {
    link.poll(input);
    const double now = now_s();
    const bool have_model = models.read(latest);
    for (int h = 0; h < 2; ++h) {
      const devices::HandInput& hand = h == 0 ? input.left : input.right;
      haptics::DeviceTip tip{hand.pose.translation, hand.velocity};
      // The model's time is the wall-clock time it was published at.
      const haptics::ForceChannels f =
          have_model && hand.has_pose ? haptics::evaluate_local_model(latest[h], params, tip, now)
                                      : haptics::ForceChannels{};
      const double age = have_model ? now - latest[h].time_s : 1e9;
      const Vec3 command = safety[h].filter(f.total(), now, age, link.connected());
      force_max = std::max(force_max, double(command.norm()));
      link.send_force(h == 0 ? devices::Hand::left : devices::Hand::right, command, now);
    }
    if (have_model && latest[0].step != last_step_seen) {
      last_step_seen = latest[0].step;
      contacts += latest[0].contact_count + latest[1].contact_count;
    }
  });
  loop.start();
  std::unique_ptr<EmulatedDevices> emulator;
  install_interrupt_handlers();
  const double end_script = script.end_time() + 0.5;
  std::uint64_t step = 0;
  while (now_s() < o.seconds && interrupt_signal() == 0) {
    const double sim_t = std::fmod(double(step) * kStep, end_script);
    const physics::StepResult r =
        session::step_session(s, session::sample_script(script, sim_t), exec);
    if (!r.ok()) break;
    ++step;
    const double published = now_s();
    models.publish({local_model(s, 0, published, step), local_model(s, 1, published, step)});
    tips.publish({tool_tip(s.stations[0]), tool_tip(s.stations[1])});
    if (!emulator) emulator = std::make_unique<EmulatedDevices>(link.port(), tips);
    // Real time: the next step at t0 + step x 5 ms.
    std::this_thread::sleep_until(t0 + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(double(step) * kStep)));
  }
  loop.stop();
  emulator.reset();
  const haptics::HapticLoopStats st = loop.stats();
  nlohmann::json j;
  j["rate_hz"] = st.rate_hz;
  j["period_p50_us"] = st.period_p50_us;
  j["period_p99_error_us"] = st.period_p99_error_us;
  j["period_max_us"] = st.period_max_us;
  j["missed_deadlines"] = st.missed_deadlines;
  j["latency_p99_us"] = st.latency_p99_us;
  j["force_max_n"] = force_max;
  j["contacts"] = contacts;
  if (o.json) {
    // Exactly the keys of the contract (issue 13); the rest is in the text report.
    std::cout << j.dump() << '\n';
  } else {
    std::cout << "haptic loop: " << st.ticks << " ticks, " << st.rate_hz << " Hz, period p50 "
              << st.period_p50_us << " us, p99 error " << st.period_p99_error_us << " us, max "
              << st.period_max_us << " us, missed deadlines " << st.missed_deadlines
              << ", latency p99 " << st.latency_p99_us << " us"
              << (st.realtime ? " (real-time priority)" : " (normal priority)")
              << "; physics steps " << step << "; OpenIGTLink messages accepted "
              << link.counters().accepted << ", refused " << link.counters().refused_total()
              << "; largest force " << force_max << " N\n";
  }
  return 0;
}

}  // namespace imasim::cli
