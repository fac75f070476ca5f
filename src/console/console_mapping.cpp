#include "console/console_mapping.hpp"

#include <algorithm>

namespace imasim::console {

namespace {

surgery::InstrumentInput instrument_input(const devices::HandInput& hand,
                                          const session::Station& station) {
  surgery::InstrumentInput in;
  if (hand.has_pose) {
    in.source = hand.frame == devices::PoseFrame::tool ? surgery::PoseSource::tool
                                                       : surgery::PoseSource::hand;
    in.pose = hand.pose;
  }
  in.clutch = hand.clutch;
  in.device_lost = hand.lost;
  if (!hand.has_buttons) return in;  // the jaws hold until the device says where they go
  const surgery::JawParams& jaws = station.instrument.jaws;
  const Real target = (1 - std::clamp(hand.jaw, Real(0), Real(1))) * jaws.max_angle;
  const Real angle = station.state.jaw_angle;
  in.jaw = target > angle + kJawDeadband   ? surgery::JawCommand::open
           : target < angle - kJawDeadband ? surgery::JawCommand::close
                                           : surgery::JawCommand::hold;
  return in;
}

surgery::PedalMode pedal_mode(haptics::CauteryMode mode) {
  switch (mode) {
    case haptics::CauteryMode::cut:
      return surgery::PedalMode::cut;
    case haptics::CauteryMode::coag:
      return surgery::PedalMode::coag;
    case haptics::CauteryMode::off:
      break;
  }
  return surgery::PedalMode::off;
}

}  // namespace

session::SessionInput to_session_input(const devices::ConsoleInput& console,
                                       const session::SurgicalSession& s) {
  session::SessionInput in;
  in.left = instrument_input(console.left, s.stations[0]);
  in.right = instrument_input(console.right, s.stations[1]);
  in.right.pedal = pedal_mode(console.pedal);
  in.right.power = console.power_w;
  in.right.device_lost = in.right.device_lost || console.pedal_lost;
  return in;
}

}  // namespace imasim::console
