#include "session/tool_tip.hpp"

namespace imasim::session {

Vec3 tool_tip(const SurgicalSession& s, int station) {
  const Station& st = s.stations[std::size_t(station)];
  if (st.instrument.kind == surgery::InstrumentKind::forceps) {
    const Vec3 upper =
        surgery::jaw_tip(st.instrument, surgery::upper_jaw_pose(st.instrument, st.state));
    const Vec3 lower =
        surgery::jaw_tip(st.instrument, surgery::lower_jaw_pose(st.instrument, st.state));
    return Real(0.5) * (upper + lower);
  }
  return st.pose.translation + s.params.cautery.electrode_length * st.pose.rotation.col(2);
}

}  // namespace imasim::session
