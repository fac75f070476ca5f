#pragma once
// OpenIGTLink messages as imasim reads and writes them (the protocol of 3D Slicer,
// PLUS and ROS bridges; Debian's libopenigtlink-dev 1.11 packs and unpacks them):
//   in:  TRANSFORM per hand (device names mapped in the scene file), in millimetres as the
//        protocol's users send them, converted to metres here, at the edge;
//        SENSOR "<hand> buttons": [clutch (0/1), jaw (0 open .. 1 closed)];
//        TRANSFORM per tool instead (a tracker on the instrument): its hinge in the scene frame;
//        SENSOR "pedal": [mode (0 off, 1 cut, 2 coag)] or [mode, power (W, 0 .. 300)];
//   out: SENSOR "<hand> force": [Fx, Fy, Fz] in newtons, in the scene frame.
// Every message is checked before use: its header, its CRC, a body no larger than the type
// needs, a known type and device name, finite values, a rotation that is one, a time stamp
// later than the device's previous one on this connection (a replayed or reordered message is
// refused; a stamp of 0 is no stamp: the message is timed by its arrival) and not far ahead of
// the sender's clock (kIgtlMaxStampLeadS). A refused message changes nothing and is counted by
// reason.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "devices/hand_input.hpp"

namespace imasim::devices {

inline constexpr std::size_t kIgtlHeaderBytes = 58;
// The largest body imasim reads: a SENSOR message of 255 values is 10 + 8 x 255 bytes.
inline constexpr std::size_t kIgtlMaxBodyBytes = 2048;

struct IgtlNames {
  std::string left_pose = "LeftHand", right_pose = "RightHand";
  std::string left_tool = "LeftTool", right_tool = "RightTool";  // tool poses (scene frame)
  std::string left_buttons = "LeftButtons", right_buttons = "RightButtons";
  std::string pedal = "Pedal";
  std::string left_force = "LeftForce", right_force = "RightForce";
};

enum class IgtlRefusal : std::uint8_t {
  bad_header,      // not an OpenIGTLink version-1 header
  oversized,       // a body larger than kIgtlMaxBodyBytes
  unknown_type,    // a type imasim does not read
  unknown_device,  // a device name the mapping does not name
  bad_body,        // a CRC mismatch or a body the type cannot unpack
  bad_values,      // non-finite values, a rotation that is not one, values out of range
  out_of_order,    // a time stamp not later than the device's previous message
  future_stamp,    // a time stamp far ahead of the sender's clock as its first messages showed
};
inline constexpr std::size_t kIgtlRefusals = 8;

// A sender's clock against the loop's on one connection (stamp minus arrival): set by its first
// stamped message; a stamp more than this ahead of it is refused, not adopted (one stamped
// 2^32 - 1 s had locked its device name for the session). Stamps this far behind it for
// kIgtlClockResetS of arrival, agreeing with each other, reset it and the order: the reference
// was the odd one (a first message stamped far ahead, a sender whose clock was stepped back).
// A single replayed old message is still refused as out of order. (unit: s)
inline constexpr double kIgtlMaxStampLeadS = 1.0;
inline constexpr double kIgtlClockResetS = 0.5;
const char* igtl_refusal_name(IgtlRefusal r);
// A device name off the wire as a report can show it: printable ASCII ('?' for any other byte),
// "(no name)" when empty.
std::string igtl_printable_name(const char* name);
const char* igtl_refusal_meaning(IgtlRefusal r);  // one line for a user

// Refusals of one device name (the header's, at most 20 characters; "" when the header could not
// be read).
struct IgtlNameRefusals {
  std::array<char, 21> name{};
  std::uint64_t count = 0;
};
inline constexpr std::size_t kIgtlRefusedNames = 16;  // names told apart; the rest are "others"

// The messages of one device name and type whose header could be read, accepted or not: what
// `imasim devices --listen` shows, so that a user can map a tracker's names to the hands.
struct IgtlArrival {
  std::array<char, 21> name{};
  std::array<char, 13> type{};
  std::uint64_t messages = 0, accepted = 0;
};
inline constexpr std::size_t kIgtlArrivals = 16;  // names and types told apart

// Peers followed at once (a tracker for each hand, a console and a pedal box): each its own
// connection, with its own clock and order.
inline constexpr std::size_t kIgtlMaxPeers = 4;

struct IgtlCounters {
  std::uint64_t accepted = 0;
  std::array<std::uint64_t, kIgtlRefusals> refused{};
  // By device name, in the order first refused (no allocation in the loop).
  std::array<IgtlNameRefusals, kIgtlRefusedNames> refused_names{};
  std::size_t named = 0;                              // entries of refused_names in use
  std::uint64_t refused_others = 0;                   // refusals of names past the table's room
  std::array<IgtlArrival, kIgtlArrivals> arrivals{};  // in the order first seen
  std::size_t arrived = 0;                            // entries of arrivals in use
  std::uint64_t refused_total() const;
  // Bit r set: refusal reason r seen at least once.
  std::uint32_t reasons_seen() const;
};

// A header's fields, once checked.
struct IgtlHeader {
  std::string type, device;
  std::uint64_t body_bytes = 0;
  double time_s = 0;
};

class IgtlDecoder {
 public:
  explicit IgtlDecoder(IgtlNames names = {});

  // The header of the next message, or empty (counted as refused) when it is not one or its
  // body is too large to read; the caller then reads `body_bytes` more (or drops the link).
  std::optional<IgtlHeader> read_header(const std::uint8_t* bytes);

  // Applies a whole message (header and body) to `input`; false (and counted) when refused.
  // `arrival_s`: when it arrived (the loop's clock, unit: s; 0: no clock, so no check of stamps
  // against it). A time stamp of 0 means unstamped (the protocol's unused stamp, which common
  // trackers send): such a message is taken in the order it arrives and timed by its arrival.
  // `sender` (< kIgtlMaxPeers): the connection it came on, whose clock and order it is checked
  // against.
  bool apply(const std::uint8_t* header, const std::uint8_t* body, std::size_t body_bytes,
             ConsoleInput& input, double arrival_s = 0, std::size_t sender = 0);

  // A new peer on connection `sender`: its time stamps are its own clock's, so ordering starts
  // afresh (a device that reconnects with its clock restarted is followed, not refused as out of
  // order).
  void start_fresh(std::size_t sender = 0);

  const IgtlCounters& counters() const { return counters_; }
  const IgtlNames& names() const { return names_; }
  // The tracker's frame in the scene: every pose that arrives is turned by its rotation and moved
  // by its translation (metres) before use. Identity by default.
  void set_tracker_to_scene(const Pose& tracker_to_scene) { tracker_to_scene_ = tracker_to_scene; }

  // The part the last accepted message drove: 0 left hand, 1 right hand, 2 pedal (-1: none yet).
  int last_part() const { return last_part_; }

 private:
  // One connection's sender as its messages showed it.
  struct Sender {
    std::array<double, 7> last_time_s{};  // per mapped device: poses, tools, buttons, pedal
    // Its clock (stamp - arrival); NaN until its first stamped message.
    double clock_offset_s = 0;
    // Since when (arrival) stamps have been far behind the clock, agreeing on this offset; NaN:
    // not.
    double behind_since_s = 0, behind_offset_s = 0;
  };

  bool refuse(IgtlRefusal r, std::string_view device);
  void count_arrival(const IgtlHeader& head, bool accepted);
  // apply's checks and effect once the header is read.
  bool apply_checked(const IgtlHeader& head, const std::uint8_t* header, const std::uint8_t* body,
                     std::size_t body_bytes, ConsoleInput& input, double arrival_s, Sender& sender);
  bool later_than_last(Sender& sender, const std::string& device, double time_s);
  // Why a stamped message's stamp is refused, or empty (and its order then recorded).
  std::optional<IgtlRefusal> stamp_problem(Sender& sender, const std::string& device, double time_s,
                                           double arrival_s);

  IgtlNames names_;
  IgtlCounters counters_;
  std::array<Sender, kIgtlMaxPeers> senders_;
  int last_part_ = -1;
  Pose tracker_to_scene_;
};

// The values of a whole SENSOR message (checked as apply checks it), or empty: for a device's
// side of the link (an emulator reading its force).
std::optional<std::vector<double>> decode_sensor(const std::uint8_t* header,
                                                 const std::uint8_t* body, std::size_t body_bytes);

// A SENSOR message with the force on one hand (unit: N), time-stamped `time_s`.
std::vector<std::uint8_t> encode_force(const std::string& device, const Vec3& force_n,
                                       double time_s);

// A TRANSFORM message of a hand pose given in metres (sent in millimetres), for emulators and
// tests.
std::vector<std::uint8_t> encode_pose(const std::string& device, const Pose& pose_m, double time_s);

// A SENSOR message of values (buttons, pedal), for emulators and tests.
std::vector<std::uint8_t> encode_values(const std::string& device,
                                        const std::vector<double>& values, double time_s);

}  // namespace imasim::devices
