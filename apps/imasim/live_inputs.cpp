#include "live_inputs.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "console/console_mapping.hpp"
#include "console/console_settings_use.hpp"
#include "devices/gamepad_device.hpp"
#include "devices/igtl_device.hpp"
#include "devices/joystick_pedal_device.hpp"
#include "devices/spacemouse_device.hpp"
#include "spawn_self.hpp"
#if IMASIM_HAS_OPENHAPTICS
#include "devices/openhaptics_device.hpp"
#endif
#if IMASIM_HAS_FORCE_DIMENSION
#include "devices/force_dimension_device.hpp"
#endif

namespace imasim::cli {

namespace {

nlohmann::ordered_json loop_report(const haptics::HapticLoopStats& s) {
  nlohmann::ordered_json j;
  j["ticks"] = s.ticks;
  j["rate_hz"] = s.rate_hz;
  j["period_p50_us"] = s.period_p50_us;
  j["period_p99_error_us"] = s.period_p99_error_us;
  j["period_max_us"] = s.period_max_us;
  j["missed_deadlines"] = s.missed_deadlines;
  j["latency_p99_us"] = s.latency_p99_us;
  j["realtime_priority"] = s.realtime;
  return j;
}

// A child emulator's play time when it plays until finish() stops it (unit: s): the longest
// device-emulator plays.
constexpr double kUntilStopped = 3600;

}  // namespace

nlohmann::ordered_json loss_report(const console::LiveConsoleStats& stats) {
  nlohmann::ordered_json lost;
  constexpr const char* kNames[console::kParts] = {"left", "right", "pedal"};
  for (std::size_t p = 0; p < console::kParts; ++p)
    lost[kNames[p]] = {{"losses", stats.losses[p].losses},
                       {"lost_s", stats.losses[p].lost_s},
                       {"held_at_end", stats.losses[p].held}};
  return lost;
}

std::vector<std::unique_ptr<devices::InputDevice>> make_live_devices(const LiveInputOptions& o,
                                                                     std::uint16_t& port) {
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  if (o.devices == "openigtlink" || o.devices == "emulator") {
    devices::IgtlDeviceConfig config = console::igtl_device_config(o.settings);
    config.link.role =
        o.client ? devices::IgtlLinkConfig::Role::client : devices::IgtlLinkConfig::Role::server;
    if (o.address) config.link.address = *o.address;
    if (o.port) config.link.port = *o.port;
    auto igtl = std::make_unique<devices::IgtlDevice>(config);  // throws IgtlLinkError
    port = igtl->link().port();
    list.push_back(std::move(igtl));
  } else if (o.devices == "gamepad") {
    list.push_back(std::make_unique<devices::GamepadDevice>(console::gamepad_mapping(o.settings)));
  } else if (o.devices == "spacemouse") {
    list.push_back(
        std::make_unique<devices::SpaceMouseDevice>(console::spacemouse_mapping(o.settings)));
  } else if (o.devices == "openhaptics") {
#if IMASIM_HAS_OPENHAPTICS
    // The names Touch Setup gives two devices (docs/haptics.md).
    list.push_back(
        std::make_unique<devices::OpenHapticsDevice>("Left Device", devices::Hand::left));
    list.push_back(
        std::make_unique<devices::OpenHapticsDevice>("Right Device", devices::Hand::right));
#else
    throw std::runtime_error(
        "this imasim was built without the OpenHaptics adapter (configure with "
        "-DIMASIM_OPENHAPTICS=ON where 3D Systems' SDK is installed)");
#endif
  } else if (o.devices == "force_dimension") {
#if IMASIM_HAS_FORCE_DIMENSION
    list.push_back(std::make_unique<devices::ForceDimensionDevice>(0, devices::Hand::left));
    list.push_back(std::make_unique<devices::ForceDimensionDevice>(1, devices::Hand::right));
#else
    throw std::runtime_error(
        "this imasim was built without the Force Dimension adapter (configure with "
        "-DIMASIM_FORCE_DIMENSION=ON where its SDK is installed)");
#endif
  } else {
    throw std::runtime_error("unknown live input '" + o.devices + "'");
  }
  // Polled after the hands' device: its pedal and clutch are the ones that count.
  if (o.pedal)
    list.push_back(
        std::make_unique<devices::JoystickPedalDevice>(console::pedal_mapping(o.settings)));
  return list;
}

pid_t spawn_emulator(const std::string& script, const std::string& scene, std::uint16_t port,
                     double seconds, bool loop) {
  std::vector<std::string> args = {"device-emulator", "--port", std::to_string(port), "--seconds",
                                   std::to_string(seconds)};
  if (!script.empty()) args.insert(args.end(), {"--script", script});  // else the built-in one
  if (loop) args.push_back("--loop");
  if (!scene.empty()) args.insert(args.end(), {"--scene", scene});
  int error = 0;
  const pid_t pid = spawn_self(args, "/dev/null", "", error);
  if (pid < 0) throw std::runtime_error("cannot start the device emulator");
  return pid;
}

LiveInputs::LiveInputs(const LiveInputOptions& o) : program_(o.program) {
  std::uint16_t port = 0;
  std::vector<std::unique_ptr<devices::InputDevice>> list = make_live_devices(o, port);
  console::LiveConsoleParams params = console::live_console_params(o.settings);
  if (!o.realtime_priority) params.loop.realtime_priority = 0;
  owned_ = std::make_unique<console::LiveConsole>(std::move(list), params);
  console_ = owned_.get();
  report_["kind"] = o.devices;
  report_["link"] = console_->device_info()[0].name;
  if (o.pedal) report_["pedal"] = console_->device_info().back().name;
  if (o.devices == "emulator")
    emulator_ = spawn_emulator(o.script_file, o.scene_file, port,
                               o.seconds > 0 ? o.seconds : kUntilStopped, o.loop_script);
  console_->start();
}

LiveInputs::~LiveInputs() {
  if (!finished_) finish();
}

session::SessionInput LiveInputs::next(const session::SurgicalSession& s) {
  return console::to_session_input(console_->latest_input(), s);
}

void LiveInputs::after_step(const session::SurgicalSession& s, std::uint64_t steps_done) {
  console_->publish(s, steps_done);
  // A refusal is said once per reason as it first happens; every one is counted in the report.
  const std::uint32_t refusals = console_->refusal_reasons_seen() & ~told_refusals_;
  for (std::size_t r = 0; r < devices::kIgtlRefusals; ++r) {
    if ((refusals & (std::uint32_t(1) << r)) == 0) continue;
    std::fprintf(stderr,
                 "%s: OpenIGTLink: a message was refused (%s: %s); each refusal is "
                 "counted by reason and device name in the JSON's devices.refused\n",
                 program_.c_str(), devices::igtl_refusal_name(devices::IgtlRefusal(r)),
                 devices::igtl_refusal_meaning(devices::IgtlRefusal(r)));
  }
  told_refusals_ |= refusals;
  // A loss is said where the user looks as it happens, not only in the report at the end.
  for (std::size_t k = 0; k < 2; ++k) {
    const bool lost = s.stations[k].device_lost;
    if (lost == told_lost_[k]) continue;
    told_lost_[k] = lost;
    std::fprintf(stderr, "%s: at %.3f s the %s's device %s\n", program_.c_str(),
                 double(s.scene.patch.world.state.time), k == 0 ? "forceps" : "hook",
                 lost ? "was lost: the instrument is held still, the cautery off"
                      : "is back: the instrument follows it again");
  }
}

nlohmann::ordered_json LiveInputs::finish() {
  if (finished_) return report_;
  finished_ = true;
  console_->stop();
  const std::vector<devices::DeviceInfo> info = console_->device_info();
  const console::LiveConsoleStats st = console_->stats();
  if (emulator_ > 0) {
    ::kill(emulator_, SIGTERM);
    int status = 0;
    ::waitpid(emulator_, &status, 0);
    emulator_ = -1;
  }
  report_["connected_at_end"] = !info.empty() && info[0].connected;
  if (!info.empty()) {
    nlohmann::ordered_json refused, by_reason = nlohmann::ordered_json::object(),
                                    by_name = nlohmann::ordered_json::object();
    std::uint64_t total = 0;
    for (const auto& [reason, n] : info[0].refused_by_reason) {
      by_reason[reason] = n;
      total += n;
    }
    for (const auto& [name, n] : info[0].refused_by_name)
      by_name[name] = n;
    refused["total"] = total;
    refused["by_reason"] = by_reason;
    refused["by_device"] = by_name;
    report_["refused"] = refused;
    report_["peers_seen"] = info[0].peers_seen;
    report_["peers_dropped"] = info[0].peers_dropped;
    report_["peers_timed_out"] = info[0].peers_timed_out;
    report_["peers_turned_away"] = info[0].peers_turned_away;
    report_["reconnects"] = info[0].reconnects;
    report_["forces_skipped"] = info[0].forces_skipped;
  }
  if (info.size() > 1 && info.back().kind == "pedal")
    report_["pedal_connected_at_end"] = info.back().connected;
  report_["haptic_loop"] = loop_report(st.loop);
  report_["force_max_n"] = st.force_max_n;
  report_["contacts"] = st.contacts;
  report_["models_rendered"] = st.models_read;
  nlohmann::ordered_json safety;
  for (int h = 0; h < 2; ++h) {
    const haptics::SafetyCounters& c = st.safety[h];
    safety[h == 0 ? "left" : "right"] = {{"non_finite", c.non_finite},
                                         {"clamped", c.clamped},
                                         {"rate_limited", c.rate_limited},
                                         {"stale_model", c.stale_model},
                                         {"device_lost", c.device_lost}};
  }
  report_["safety"] = safety;
  report_["lost"] = loss_report(st);
  return report_;
}

}  // namespace imasim::cli
