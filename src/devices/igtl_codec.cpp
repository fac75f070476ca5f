#include "devices/igtl_codec.hpp"

#include <Eigen/Geometry>

#include <igtlMessageHeader.h>
#include <igtlSensorMessage.h>
#include <igtlTransformMessage.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace imasim::devices {

namespace {

constexpr double kFraction = 4294967296.0;
constexpr std::size_t kTransformBodyBytes = 48;  // the header's time stamp: 2^-32 s units
constexpr Real kMetresPerMillimetre = Real(0.001);
// A TRANSFORM's rotation may carry float rounding; more than this is not a rotation.
constexpr Real kRotationTolerance = Real(1e-3);
// The largest hand position accepted (unit: m): a console's workspace is tens of centimetres.
constexpr Real kMaxHandPosition = 2;

enum DeviceSlot : std::size_t {
  kLeftPose,
  kRightPose,
  kLeftButtons,
  kRightButtons,
  kPedal,
  kLeftTool,
  kRightTool
};
// The electrosurgical generator's range (unit: W).
constexpr double kMaxPowerW = 300;

double stamp_seconds(igtl::MessageBase& m) {
  unsigned int sec = 0, frac = 0;
  m.GetTimeStamp(&sec, &frac);
  return double(sec) + double(frac) / kFraction;
}

void set_stamp(igtl::MessageBase& m, double time_s) {
  // The header's seconds are 32 bits: clamped, so that a bad clock cannot overflow the cast.
  const double t = std::clamp(std::isfinite(time_s) ? time_s : 0.0, 0.0, 4294967295.0);
  const auto sec = static_cast<unsigned int>(std::floor(t));
  const auto frac = static_cast<unsigned int>(std::min((t - sec) * kFraction, kFraction - 1));
  m.SetTimeStamp(sec, frac);
}

std::vector<std::uint8_t> packed(igtl::MessageBase& m) {
  m.Pack();
  const auto* p = static_cast<const std::uint8_t*>(m.GetPackPointer());
  return std::vector<std::uint8_t>(p, p + m.GetPackSize());
}

// The header bytes into a MessageHeader (unpacked), or null when they are not a header.
igtl::MessageHeader::Pointer unpack_header(const std::uint8_t* bytes) {
  igtl::MessageHeader::Pointer h = igtl::MessageHeader::New();
  h->InitPack();
  std::memcpy(h->GetPackPointer(), bytes, kIgtlHeaderBytes);
  if (!(h->Unpack() & igtl::MessageHeader::UNPACK_HEADER)) return nullptr;
  return h;
}

// The sensor values of a whole SENSOR message, or empty when the body does not unpack.
std::optional<std::vector<double>> sensor_values(const igtl::MessageHeader::Pointer& h,
                                                 const std::uint8_t* body, std::size_t bytes) {
  // The body is its value count (1 byte), a status byte, a unit (8 bytes), then the values (8
  // bytes each). Checked before the library reads it: it trusts the count and reads past a
  // shorter body (found by fuzzing, fuzz/corpus/igtl_message/regression_sensor_count).
  if (bytes < 10 || std::size_t(body[0]) * 8 + 10 != bytes) return std::nullopt;
  igtl::SensorMessage::Pointer m = igtl::SensorMessage::New();
  m->SetMessageHeader(h);
  m->AllocatePack();
  if (std::size_t(m->GetPackBodySize()) != bytes) return std::nullopt;
  std::memcpy(m->GetPackBodyPointer(), body, bytes);
  if (!(m->Unpack(1) & igtl::MessageHeader::UNPACK_BODY)) return std::nullopt;
  if (std::size_t(m->GetLength()) * 8 + 10 != bytes) return std::nullopt;
  std::vector<double> values(m->GetLength());
  for (unsigned k = 0; k < m->GetLength(); ++k)
    values[k] = m->GetValue(k);
  return values;
}

}  // namespace

const char* igtl_refusal_meaning(IgtlRefusal r) {
  switch (r) {
    case IgtlRefusal::bad_header:
      return "not an OpenIGTLink version 1 or 2 header; the peer is dropped";
    case IgtlRefusal::oversized:
      return "a body larger than imasim reads; the peer is dropped";
    case IgtlRefusal::unknown_type:
      return "a message type imasim does not read (TRANSFORM and SENSOR only)";
    case IgtlRefusal::unknown_device:
      return "a device name the scene's [devices] mapping does not name";
    case IgtlRefusal::bad_body:
      return "a CRC mismatch or a body its type cannot unpack";
    case IgtlRefusal::bad_values:
      return "non-finite values, a rotation that is not one, or values out of range";
    case IgtlRefusal::out_of_order:
      return "a time stamp not later than the device's previous one";
    case IgtlRefusal::future_stamp:
      return "a time stamp more than 1 s ahead of the sender's clock as its first messages showed";
  }
  return "?";
}

std::string igtl_printable_name(const char* name) {
  std::string out(name);
  for (char& c : out)
    if (c < 0x20 || c > 0x7e) c = '?';
  return out.empty() ? std::string("(no name)") : out;
}

const char* igtl_refusal_name(IgtlRefusal r) {
  switch (r) {
    case IgtlRefusal::bad_header:
      return "bad_header";
    case IgtlRefusal::oversized:
      return "oversized";
    case IgtlRefusal::unknown_type:
      return "unknown_type";
    case IgtlRefusal::unknown_device:
      return "unknown_device";
    case IgtlRefusal::bad_body:
      return "bad_body";
    case IgtlRefusal::bad_values:
      return "bad_values";
    case IgtlRefusal::out_of_order:
      return "out_of_order";
    case IgtlRefusal::future_stamp:
      return "future_stamp";
  }
  return "?";
}

std::uint32_t IgtlCounters::reasons_seen() const {
  std::uint32_t bits = 0;
  for (std::size_t r = 0; r < refused.size(); ++r)
    bits |= refused[r] > 0 ? std::uint32_t(1) << r : 0u;
  return bits;
}

std::uint64_t IgtlCounters::refused_total() const {
  std::uint64_t n = 0;
  for (const std::uint64_t r : refused)
    n += r;
  return n;
}

IgtlDecoder::IgtlDecoder(IgtlNames names) : names_(std::move(names)) {
  for (std::size_t k = 0; k < senders_.size(); ++k)
    start_fresh(k);
}

void IgtlDecoder::start_fresh(std::size_t sender) {
  Sender& s = senders_[std::min(sender, senders_.size() - 1)];
  s.last_time_s.fill(-std::numeric_limits<double>::infinity());
  s.clock_offset_s = s.behind_since_s = s.behind_offset_s =
      std::numeric_limits<double>::quiet_NaN();
}

std::optional<IgtlRefusal> IgtlDecoder::stamp_problem(Sender& s, const std::string& device,
                                                      double time_s, double arrival_s) {
  if (arrival_s > 0) {
    const double offset = time_s - arrival_s;
    if (std::isnan(s.clock_offset_s)) s.clock_offset_s = offset;
    const double lead = offset - s.clock_offset_s;
    if (lead > kIgtlMaxStampLeadS) return IgtlRefusal::future_stamp;
    if (lead < -kIgtlMaxStampLeadS) {
      if (std::isnan(s.behind_since_s) ||
          !(std::abs(offset - s.behind_offset_s) <= kIgtlMaxStampLeadS)) {
        s.behind_since_s = arrival_s, s.behind_offset_s = offset;
      } else if (arrival_s - s.behind_since_s >= kIgtlClockResetS) {
        // The clock and the order start again from this message.
        s.last_time_s.fill(-std::numeric_limits<double>::infinity());
        s.behind_since_s = s.behind_offset_s = std::numeric_limits<double>::quiet_NaN();
        s.clock_offset_s = offset;
      }
    } else {
      s.behind_since_s = std::numeric_limits<double>::quiet_NaN();
    }
  }
  if (!later_than_last(s, device, time_s)) return IgtlRefusal::out_of_order;
  return std::nullopt;
}

void IgtlDecoder::count_arrival(const IgtlHeader& head, bool accepted) {
  const std::string_view name = std::string_view(head.device).substr(0, 20);
  const std::string_view type = std::string_view(head.type).substr(0, 12);
  IgtlCounters& c = counters_;
  IgtlArrival* entry = nullptr;
  for (std::size_t k = 0; k < c.arrived && entry == nullptr; ++k)
    if (std::string_view(c.arrivals[k].name.data()) == name &&
        std::string_view(c.arrivals[k].type.data()) == type)
      entry = &c.arrivals[k];
  if (entry == nullptr) {
    if (c.arrived == c.arrivals.size()) return;  // the table is full: counted as refusals only
    entry = &c.arrivals[c.arrived++];
    name.copy(entry->name.data(), name.size());
    type.copy(entry->type.data(), type.size());
  }
  ++entry->messages;
  if (accepted) ++entry->accepted;
}

bool IgtlDecoder::refuse(IgtlRefusal r, std::string_view device) {
  ++counters_.refused[std::size_t(r)];
  device = device.substr(0, 20);
  IgtlCounters& c = counters_;
  for (std::size_t k = 0; k < c.named; ++k) {
    if (std::string_view(c.refused_names[k].name.data()) == device) {
      ++c.refused_names[k].count;
      return false;
    }
  }
  if (c.named == c.refused_names.size()) {
    ++c.refused_others;
    return false;
  }
  IgtlNameRefusals& entry = c.refused_names[c.named++];
  device.copy(entry.name.data(), device.size());
  entry.name[device.size()] = '\0';
  entry.count = 1;
  return false;
}

std::optional<IgtlHeader> IgtlDecoder::read_header(const std::uint8_t* bytes) {
  const igtl::MessageHeader::Pointer h = unpack_header(bytes);
  if (!h) {
    refuse(IgtlRefusal::bad_header, {});
    return std::nullopt;
  }
  // The version field: the first two bytes, big-endian.
  const unsigned version = (unsigned(bytes[0]) << 8) | bytes[1];
  if (version != 1 && version != 2) {
    refuse(IgtlRefusal::bad_header, h->GetDeviceName());
    return std::nullopt;
  }
  IgtlHeader out;
  out.type = h->GetDeviceType();
  out.device = h->GetDeviceName();
  out.body_bytes = std::uint64_t(h->GetBodySizeToRead());
  out.time_s = stamp_seconds(*h);
  if (out.body_bytes > kIgtlMaxBodyBytes) {
    refuse(IgtlRefusal::oversized, out.device);
    return std::nullopt;
  }
  return out;
}

bool IgtlDecoder::later_than_last(Sender& s, const std::string& device, double time_s) {
  std::size_t slot = 0;
  if (device == names_.left_pose)
    slot = kLeftPose;
  else if (device == names_.right_pose)
    slot = kRightPose;
  else if (device == names_.left_tool)
    slot = kLeftTool;
  else if (device == names_.right_tool)
    slot = kRightTool;
  else if (device == names_.left_buttons)
    slot = kLeftButtons;
  else if (device == names_.right_buttons)
    slot = kRightButtons;
  else
    slot = kPedal;
  if (!(time_s > s.last_time_s[slot])) return false;
  s.last_time_s[slot] = time_s;
  return true;
}

bool IgtlDecoder::apply(const std::uint8_t* header, const std::uint8_t* body,
                        std::size_t body_bytes, ConsoleInput& input, double arrival_s,
                        std::size_t sender) {
  const std::optional<IgtlHeader> head = read_header(header);
  if (!head) return false;
  const bool accepted = apply_checked(*head, header, body, body_bytes, input, arrival_s,
                                      senders_[std::min(sender, senders_.size() - 1)]);
  count_arrival(*head, accepted);
  return accepted;
}

bool IgtlDecoder::apply_checked(const IgtlHeader& header_fields, const std::uint8_t* header,
                                const std::uint8_t* body, std::size_t body_bytes,
                                ConsoleInput& input, double arrival_s, Sender& sender) {
  const IgtlHeader* head = &header_fields;
  // An unused stamp is 0 (the protocol): such messages come in TCP's order, timed on arrival.
  const bool unstamped = head->time_s == 0;
  const double time_s = unstamped ? arrival_s : head->time_s;
  auto stamp_refused = [&]() -> std::optional<IgtlRefusal> {
    if (unstamped) return std::nullopt;
    return stamp_problem(sender, head->device, head->time_s, arrival_s);
  };
  if (head->body_bytes != body_bytes) return refuse(IgtlRefusal::bad_body, head->device);
  const igtl::MessageHeader::Pointer h = unpack_header(header);
  const std::string& device = head->device;
  const bool tool = device == names_.left_tool || device == names_.right_tool;
  const bool pose = tool || device == names_.left_pose || device == names_.right_pose;
  const bool buttons = device == names_.left_buttons || device == names_.right_buttons;
  const bool pedal = device == names_.pedal;
  if (head->type == "TRANSFORM") {
    if (!pose) return refuse(IgtlRefusal::unknown_device, head->device);
    // Twelve 4-byte floats. Checked before the library reads it: it sizes its buffer by the
    // header and reads 48 bytes whatever the header said (found by fuzzing,
    // fuzz/corpus/igtl_message/regression_transform_size).
    if (body_bytes != kTransformBodyBytes) return refuse(IgtlRefusal::bad_body, head->device);
    igtl::TransformMessage::Pointer m = igtl::TransformMessage::New();
    m->SetMessageHeader(h);
    m->AllocatePack();
    if (std::size_t(m->GetPackBodySize()) != body_bytes)
      return refuse(IgtlRefusal::bad_body, head->device);
    std::memcpy(m->GetPackBodyPointer(), body, body_bytes);
    if (!(m->Unpack(1) & igtl::MessageHeader::UNPACK_BODY))
      return refuse(IgtlRefusal::bad_body, head->device);
    igtl::Matrix4x4 t;
    m->GetMatrix(t);
    Mat3 r;
    Vec3 p;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        r(i, j) = Real(t[i][j]);
      p(i) = Real(t[i][3]) * kMetresPerMillimetre;  // mm on the wire, m inside
    }
    if (!r.allFinite() || !p.allFinite() || p.cwiseAbs().maxCoeff() > kMaxHandPosition ||
        !((r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff() < kRotationTolerance) ||
        !(r.determinant() > 0)) {
      return refuse(IgtlRefusal::bad_values, head->device);
    }
    if (const auto why = stamp_refused()) return refuse(*why, head->device);
    // Into the scene's frame (a tracker's own frame is rarely the scene's).
    r = tracker_to_scene_.rotation * r;
    p = tracker_to_scene_.rotation * p + tracker_to_scene_.translation;
    const bool left = device == names_.left_pose || device == names_.left_tool;
    HandInput& hand = input.hand(left ? Hand::left : Hand::right);
    const PoseFrame frame = tool ? PoseFrame::tool : PoseFrame::hand;
    if (hand.has_pose && hand.frame == frame && time_s > hand.time_s) {
      hand.velocity = (p - hand.pose.translation) / Real(time_s - hand.time_s);
    }
    // Re-orthonormalised: the wire's floats leave a rotation up to the tolerance off, and what
    // reaches the physics (and a recorded stream) is an exact one.
    hand.pose.rotation = Eigen::Quaternion<Real>(r).normalized().toRotationMatrix();
    hand.pose.translation = p;
    hand.frame = frame;
    hand.time_s = time_s;
    hand.has_pose = true;
    last_part_ = left ? 0 : 1;
    ++counters_.accepted;
    return true;
  }
  if (head->type == "SENSOR") {
    if (!buttons && !pedal) return refuse(IgtlRefusal::unknown_device, head->device);
    const std::optional<std::vector<double>> values = sensor_values(h, body, body_bytes);
    if (!values) return refuse(IgtlRefusal::bad_body, head->device);
    const std::vector<double>& v = *values;
    for (const double x : v)
      if (!std::isfinite(x)) return refuse(IgtlRefusal::bad_values, head->device);
    if (buttons) {
      if (v.size() != 2 || (v[0] != 0 && v[0] != 1) || v[1] < 0 || v[1] > 1)
        return refuse(IgtlRefusal::bad_values, head->device);
      if (const auto why = stamp_refused()) return refuse(*why, head->device);
      HandInput& hand = input.hand(device == names_.left_buttons ? Hand::left : Hand::right);
      hand.has_buttons = true;
      hand.clutch = v[0] == 1;
      hand.jaw = Real(v[1]);
      last_part_ = device == names_.left_buttons ? 0 : 1;
    } else {
      if (v.empty() || v.size() > 2 || (v[0] != 0 && v[0] != 1 && v[0] != 2) ||
          (v.size() == 2 && !(v[1] >= 0 && v[1] <= kMaxPowerW)))
        return refuse(IgtlRefusal::bad_values, head->device);
      if (const auto why = stamp_refused()) return refuse(*why, head->device);
      input.pedal = static_cast<haptics::CauteryMode>(int(v[0]));
      if (v.size() == 2) input.power_w = Real(v[1]);
      last_part_ = 2;
    }
    ++counters_.accepted;
    return true;
  }
  return refuse(IgtlRefusal::unknown_type, head->device);
}

std::optional<std::vector<double>> decode_sensor(const std::uint8_t* header,
                                                 const std::uint8_t* body, std::size_t body_bytes) {
  const igtl::MessageHeader::Pointer h = unpack_header(header);
  if (!h || std::string(h->GetDeviceType()) != "SENSOR" ||
      std::uint64_t(h->GetBodySizeToRead()) != body_bytes || body_bytes > kIgtlMaxBodyBytes) {
    return std::nullopt;
  }
  return sensor_values(h, body, body_bytes);
}

std::vector<std::uint8_t> encode_force(const std::string& device, const Vec3& force_n,
                                       double time_s) {
  return encode_values(device, {double(force_n.x()), double(force_n.y()), double(force_n.z())},
                       time_s);
}

std::vector<std::uint8_t> encode_pose(const std::string& device, const Pose& pose_m,
                                      double time_s) {
  igtl::TransformMessage::Pointer m = igtl::TransformMessage::New();
  m->SetDeviceName(device.c_str());
  set_stamp(*m, time_s);
  igtl::Matrix4x4 t;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      t[i][j] = i == 3 ? (j == 3 ? 1.0f : 0.0f)
                       : (j == 3 ? float(pose_m.translation(i) / kMetresPerMillimetre)
                                 : float(pose_m.rotation(i, j)));
  m->SetMatrix(t);
  return packed(*m);
}

std::vector<std::uint8_t> encode_values(const std::string& device,
                                        const std::vector<double>& values, double time_s) {
  igtl::SensorMessage::Pointer m = igtl::SensorMessage::New();
  m->SetDeviceName(device.c_str());
  set_stamp(*m, time_s);
  m->SetLength(static_cast<unsigned>(values.size()));
  for (unsigned k = 0; k < values.size(); ++k)
    m->SetValue(k, values[k]);
  return packed(*m);
}

}  // namespace imasim::devices
