#pragma once
// The session's event stream (SPEC S6 scoring reads it): every grasp, release, cut, cautery
// switch, contact with the IMA, the heart or the chest wall, and injury, time-stamped with the
// simulated time of the step it happened in. Plain values, no strings: cheap to record at every
// step and to publish to the recorder.
#include <cstdint>
#include <vector>

#include "math/types.hpp"

namespace imasim::surgery {

enum class EventKind : std::uint8_t {
  grasp,          // jaws closed on tissue; count = particles held
  release,        // jaws opened; count = particles let go
  fascia_cut,     // count = edges cut along the path this step
  strand_cut,     // count = strands cut this step
  cautery_on,     // pedal pressed; value = power (unit: W)
  cautery_off,    // pedal released
  contact_begin,  // the instrument touches the tissue named; count = particles, value = depth (m)
  contact_end,    // it no longer does
  injury,         // heat on the IMA past its injury threshold; count = particles, value = the
                  // largest temperature rise (unit: K)
  cut_refused,    // a fascia cut not made: no spare vertices left (a warning, never silent)
  fragment_vaporised,  // small free pieces of fascia taken out after a cut; count = triangles,
                       // value = their rest area (unit: m^2)
  strand_torn,         // strands stretched past their tear_stretch; count = strands, value =
                       // the largest stretch (ends' distance over rest distance)
  device_lost,         // the device driving the instrument (its hand or pedal) went away: it is
                       // held still with no energy
  device_restored,     // that device is back and drives the instrument again
};

enum class Tissue : std::uint8_t { none, fascia, ima, fat, heart, chest_wall };
inline constexpr int kTissueCount = 6;

struct Event {
  double time = 0;  // simulated (unit: s)
  EventKind kind = EventKind::grasp;
  std::uint8_t instrument = 0;  // index of the instrument (0 left, 1 right)
  Tissue tissue = Tissue::none;
  std::uint32_t count = 0;
  Real value = 0;
};

struct EventLog {
  std::vector<Event> events;
  void add(double time, EventKind kind, std::uint8_t instrument, Tissue tissue,
           std::uint32_t count = 0, Real value = 0) {
    events.push_back({time, kind, instrument, tissue, count, value});
  }
  std::size_t count(EventKind kind) const {
    std::size_t n = 0;
    for (const Event& e : events)
      n += e.kind == kind ? 1u : 0u;
    return n;
  }
};

const char* to_string(EventKind kind);
const char* to_string(Tissue tissue);

}  // namespace imasim::surgery
