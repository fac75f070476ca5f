#include "console/live_console.hpp"

#include <algorithm>

#include "console/local_model_of.hpp"

namespace imasim::console {

namespace {

std::vector<std::array<bool, kParts>> drives_of(
    const std::vector<std::unique_ptr<devices::InputDevice>>& list) {
  std::vector<std::array<bool, kParts>> out;
  for (const auto& d : list) {
    const devices::DeviceInfo info = d->info();
    out.push_back({info.drives_left, info.drives_right, info.drives_pedal});
  }
  return out;
}

// One source a part: a device's hold on each part it drives, lost on its own (a peer of a device
// that serves several, a pedal box beside a tracker, can vanish while the others stay).
std::vector<std::array<bool, kParts>> sources_of(
    const std::vector<std::array<bool, kParts>>& drives, std::vector<std::size_t>& device,
    std::vector<std::size_t>& part) {
  std::vector<std::array<bool, kParts>> out;
  for (std::size_t k = 0; k < drives.size(); ++k) {
    for (std::size_t p = 0; p < kParts; ++p) {
      if (!drives[k][p]) continue;
      std::array<bool, kParts> only{};
      only[p] = true;
      out.push_back(only);
      device.push_back(k);
      part.push_back(p);
    }
  }
  return out;
}

}  // namespace

LiveConsole::LiveConsole(std::vector<std::unique_ptr<devices::InputDevice>> devices,
                         const LiveConsoleParams& params)
    : params_(params),
      devices_(std::move(devices)),
      drives_(drives_of(devices_)),
      t0_(std::chrono::steady_clock::now()),
      guard_(sources_of(drives_, source_device_, source_part_)),
      connected_(source_device_.size(), false),
      parts_up_(devices_.size(), std::array<bool, kParts>{}),
      tremor_{devices::TremorFilter(params.tremor), devices::TremorFilter(params.tremor)},
      safety_{haptics::ForceSafety(params.safety, 0.0), haptics::ForceSafety(params.safety, 0.0)},
      loop_(params.loop, [this](double) { tick(now_s()); }) {
  loop_.at_thread_exit([this] {
    for (const auto& d : devices_)
      d->polling_thread_ending();
  });
}

LiveConsole::~LiveConsole() {
  stop();
}

void LiveConsole::start() {
  const double now = now_s();
  for (haptics::ForceSafety& s : safety_)
    s.restart_ramp(now);
  loop_.start();
}

void LiveConsole::stop() {
  loop_.stop();
}

double LiveConsole::now_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
}

devices::ConsoleInput LiveConsole::latest_input() {
  inputs_.read(physics_side_input_);
  return physics_side_input_;
}

void LiveConsole::publish(const session::SurgicalSession& s, std::uint64_t step) {
  const double now = now_s();
  models_.publish({local_model_of(s, 0, now, step), local_model_of(s, 1, now, step)});
}

void LiveConsole::publish_models(const std::array<haptics::LocalModel, 2>& models) {
  models_.publish(models);
}

void LiveConsole::tick(double now) {
  std::uint32_t refusals = 0;
  std::uint64_t refused = 0;
  for (std::size_t k = 0; k < devices_.size(); ++k) {
    devices_[k]->poll(now, raw_);
    parts_up_[k] = devices_[k]->parts_connected();
    refusals |= devices_[k]->refusal_reasons();
    refused += devices_[k]->refused_total();
  }
  for (std::size_t s = 0; s < connected_.size(); ++s)
    connected_[s] = parts_up_[source_device_[s]][source_part_[s]];
  refused_total_.store(refused, std::memory_order_relaxed);
  if (ticks_++ % kTallyTicks == 0) {
    DeviceTally tally;
    for (const auto& d : devices_)
      d->add_counts(tally.counts);
    tally.losses = guard_.parts();
    tally.time_s = now;
    tallies_.publish(tally);
  }
  if ((refusals & ~refusals_seen_.load(std::memory_order_relaxed)) != 0)
    refusals_seen_.fetch_or(refusals, std::memory_order_relaxed);
  // A lost device's parts are released at this very tick (loss_guard.hpp).
  const std::array<bool, 2> resumed =
      guard_.apply(now, connected_, last_step_seen_, raw_, guarded_);
  // The physics sees the filtered hands; the force is rendered against them too (what the
  // instrument follows).
  devices::ConsoleInput filtered = guarded_;
  for (int h = 0; h < 2; ++h) {
    devices::HandInput& hand = filtered.hand(devices::Hand(h));
    if (resumed[std::size_t(h)]) tremor_[h].reset();  // a returned device starts afresh
    if (hand.has_pose) hand.pose.translation = tremor_[h].filter(hand.pose.translation);
  }
  inputs_.publish(filtered);

  const bool have_model = models_.read(latest_);
  if (have_model && latest_[0].step != last_step_seen_) {
    last_step_seen_ = latest_[0].step;
    ++stats_.models_read;
    stats_.contacts += latest_[0].contact_count + latest_[1].contact_count;
  }
  for (int h = 0; h < 2; ++h) {
    const devices::Hand hand_id = devices::Hand(h);
    const devices::HandInput& hand = filtered.hand(hand_id);
    // Releasing the clutch brings hand and tool together again: the force ramps in anew.
    if (clutch_[h] && !hand.clutch) safety_[h].restart_ramp(now);
    clutch_[h] = hand.clutch;
    // A held hand gets no force from this tick on, even once its device is back.
    bool device_ok = false;
    for (std::size_t s = 0; s < connected_.size(); ++s)
      device_ok = device_ok || (source_part_[s] == std::size_t(h) && connected_[s]);
    device_ok = device_ok && !hand.lost;
    haptics::ForceChannels f;
    if (have_model && hand.has_pose && !hand.clutch) {
      const haptics::LocalModel& m = latest_[h];
      f = haptics::evaluate_local_model(
          m, params_.forces, haptics::device_in_scene(m, hand.pose.translation, hand.velocity),
          now);
    }
    const double age = have_model ? now - latest_[h].time_s : 1e9;
    const Vec3 command = safety_[h].filter(f.total(), now, age, device_ok);
    stats_.force_max_n = std::max(stats_.force_max_n, command.norm());
    for (const auto& d : devices_)
      d->send_force(hand_id, command, now);
  }
}

LiveConsoleStats LiveConsole::stats() const {
  LiveConsoleStats s = stats_;
  s.loop = loop_.stats();
  for (int h = 0; h < 2; ++h)
    s.safety[h] = safety_[h].counters();
  s.losses = guard_.parts();
  s.refused = refused_total();
  return s;
}

DeviceTally LiveConsole::device_tally() {
  tallies_.read(tally_read_);
  return tally_read_;
}

std::vector<devices::DeviceInfo> LiveConsole::device_info() const {
  std::vector<devices::DeviceInfo> out;
  for (const auto& d : devices_)
    out.push_back(d->info());
  return out;
}

}  // namespace imasim::console
