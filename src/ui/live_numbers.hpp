#pragma once
// What the physics thread tells the window about the session, about 60 times a second: plain
// values with no pointers and nothing to allocate, exchanged whole through a lock-free latest
// value (base::LatestValue), so the panels read a consistent set from one step.
#include <array>
#include <cstdint>

#include "console/device_tally.hpp"
#include "math/types.hpp"
#include "surgery/events.hpp"
#include "surgery/pedal.hpp"

namespace imasim::ui {

// The force history the panels plot: the last few seconds, oldest first.
inline constexpr std::size_t kForceHistory = 240;  // 4 s at the 60 Hz frame rate

struct HandNumbers {
  Real jaw_angle_rad = 0;
  bool clutch = false;
  // eq. 17-19 on the step's local model with the device where the hand asks (unit: N).
  Real force_normal = 0, force_tangential = 0, force_thermal = 0;
  surgery::Tissue contact = surgery::Tissue::none;  // pressed the most
  bool blocked_by_heart = false, blocked_by_wall = false;
  bool device_lost = false;  // its device is gone: held still, no energy
  // Per channel (normal, tangential, thermal), oldest first (unit: N).
  std::array<std::array<float, kForceHistory>, 3> history{};
};

enum class SimState : std::uint8_t {
  starting,  // building the first session
  running,
  paused,
  restarting,  // building a new session
  finished,    // reached its end time or was ended: the score card is ready
  failed,      // a step was refused (diverged): the message says why
};

const char* to_string(SimState state);

struct LiveNumbers {
  SimState state = SimState::starting;
  std::uint64_t session = 0;  // counts restarts: the panels clear their history on a new one
  double time_s = 0;          // simulated (unit: s)
  std::uint64_t steps = 0;
  double realtime_factor = 0;  // simulated over wall-clock seconds, recent (-)
  double running_s = 0;        // wall-clock time this session spent running (unit: s)
  double step_ms = 0;          // the latest step's wall-clock time (unit: ms)
  bool beating = true;         // the heart of this session
  bool beating_next = true;    // what a restart will use
  Real heart_rate_bpm = 0;
  Real heart_phase = 0;              // cycle fraction [0, 1)
  std::array<HandNumbers, 2> hands;  // forceps, hook
  surgery::PedalMode pedal = surgery::PedalMode::off;
  Real power_w = 0;     // the generator's setting (unit: W)
  Real optics_rad = 0;  // the endoscope's optics (unit: rad)
  std::uint64_t events = 0, fascia_edges_cut = 0, strands_cut = 0, strands_total = 0;
  std::uint64_t strands_torn = 0;  // pulled apart, not divided (tissue/strand_tear.hpp)
  std::uint64_t ima_injuries = 0;  // injury events
  std::uint64_t grasps = 0;
  std::uint64_t devices_lost = 0;     // device_lost events
  std::uint64_t device_refusals = 0;  // device messages refused (run's devices.refused)
  // By reason and name, the peers, how long each part was lost (with a live console).
  bool has_device_tally = false;
  console::DeviceTally device_tally;
  // contact_begin events per tissue (surgery::Tissue's order): touches of the heart, the IMA...
  std::array<std::uint64_t, surgery::kTissueCount> contacts_begun{};
  std::uint32_t instrument_collisions = 0;  // tips closer than 5 mm, counted once per approach
  std::uint32_t heart_contacts = 0;         // tissue particles on the heart now
  bool sai_available = false;
  std::array<Real, 2> sai{};  // eq. 20 so far per instrument (-)
  bool recording = false;
  std::uint64_t recorded_rows = 0;
  std::array<char, 200> message{};  // the latest note for the user ("" when none)
};

}  // namespace imasim::ui
