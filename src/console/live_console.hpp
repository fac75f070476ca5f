#pragma once
// The console in real time: the devices, read at 1 kHz on the haptic loop's thread,
// feed the physics through a lock-free latest value; each physics step publishes its local
// models back the same way; the loop renders eq. 17-19 against the newest hand pose and sends
// each hand's force through its safety filter. Neither side ever waits on the other.
//   haptic thread: poll devices -> release what lost devices drove (LossGuard) -> tremor filter
//                  -> publish ConsoleInput
//                  read LocalModels -> force per hand -> ForceSafety -> devices
//   physics thread: latest_input() -> step_session -> publish(session)
#include <array>
#include <atomic>
#include <chrono>
#include <memory>
#include <vector>

#include "base/latest_value.hpp"
#include "console/device_tally.hpp"
#include "console/loss_guard.hpp"
#include "devices/input_device.hpp"
#include "devices/tremor_filter.hpp"
#include "haptics/force_safety.hpp"
#include "haptics/haptic_loop.hpp"
#include "haptics/local_model.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

struct LiveConsoleParams {
  haptics::HapticLoopConfig loop;
  haptics::ForceModelParams forces = haptics::default_force_model_params();
  haptics::SafetyParams safety;
  devices::TremorFilterParams tremor;
};

struct LiveConsoleStats {
  haptics::HapticLoopStats loop;
  Real force_max_n = 0;           // largest command sent (unit: N)
  std::uint64_t contacts = 0;     // contacts in the models the loop rendered, once per model
  std::uint64_t models_read = 0;  // distinct physics steps the loop rendered
  std::array<haptics::SafetyCounters, 2> safety{};
  std::array<PartLoss, kParts> losses{};  // left hand, right hand, pedal
  std::uint64_t refused = 0;              // messages the devices refused
};

class LiveConsole {
 public:
  LiveConsole(std::vector<std::unique_ptr<devices::InputDevice>> devices,
              const LiveConsoleParams& params);
  ~LiveConsole();
  LiveConsole(const LiveConsole&) = delete;
  LiveConsole& operator=(const LiveConsole&) = delete;

  void start();
  void stop();  // joins the loop; safe twice
  // Seconds on the console's steady clock (the loop's and the models' time base).
  double now_s() const;

  // Physics thread: the newest console input (all defaults until the devices said anything).
  devices::ConsoleInput latest_input();
  // Physics thread: the local models of the step just taken.
  void publish(const session::SurgicalSession& session, std::uint64_t step);
  // The same with models made elsewhere (tests, other front ends); time_s on now_s()'s clock.
  void publish_models(const std::array<haptics::LocalModel, 2>& models);

  // After stop(): the loop's figures and what the safety filters did.
  LiveConsoleStats stats() const;
  // Any thread: the refusal reasons the devices have reported so far (bit r: reason r in the
  // devices' own numbering, OpenIGTLink's IgtlRefusal today), so that each can be said once.
  std::uint32_t refusal_reasons_seen() const {
    return refusals_seen_.load(std::memory_order_relaxed);
  }
  // Any thread: the messages the devices refused so far, all told.
  std::uint64_t refused_total() const { return refused_total_.load(std::memory_order_relaxed); }
  // One reader thread (the physics'): the newest tally, or the last one read when none is newer.
  DeviceTally device_tally();
  // The devices' descriptions (any thread while stopped; the loop owns them while running).
  std::vector<devices::DeviceInfo> device_info() const;

 private:
  using Models = std::array<haptics::LocalModel, 2>;
  void tick(double now_s);

  LiveConsoleParams params_;
  std::vector<std::unique_ptr<devices::InputDevice>> devices_;
  std::vector<std::array<bool, kParts>> drives_;  // per device: left, right, pedal
  std::chrono::steady_clock::time_point t0_;
  base::LatestValue<devices::ConsoleInput> inputs_;
  base::LatestValue<Models> models_;
  devices::ConsoleInput physics_side_input_{};
  // Haptic thread only.
  devices::ConsoleInput raw_{};      // as the devices wrote it
  devices::ConsoleInput guarded_{};  // with what lost devices drove released
  // The sources of the parts: one a part a device drives (its device and part), each lost on its
  // own; the guard is over them.
  std::vector<std::size_t> source_device_, source_part_;
  LossGuard guard_;
  std::vector<bool> connected_;                     // per source, this tick
  std::vector<std::array<bool, kParts>> parts_up_;  // per device, this tick
  std::array<devices::TremorFilter, 2> tremor_;
  std::array<haptics::ForceSafety, 2> safety_;
  std::array<bool, 2> clutch_{false, false};
  Models latest_{};
  std::uint64_t last_step_seen_ = 0;
  LiveConsoleStats stats_;
  std::atomic<std::uint32_t> refusals_seen_{0};
  std::atomic<std::uint64_t> refused_total_{0};
  base::LatestValue<DeviceTally> tallies_;
  DeviceTally tally_read_{};  // the reader's
  std::uint64_t ticks_ = 0;
  haptics::HapticLoop loop_;
};

}  // namespace imasim::console
