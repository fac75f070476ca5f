#include "session_report.hpp"

namespace imasim::cli {

void add_session_report(nlohmann::ordered_json& out, const session::SurgicalSession& s) {
  nlohmann::ordered_json events = nlohmann::ordered_json::object();
  for (surgery::EventKind kind :
       {surgery::EventKind::grasp, surgery::EventKind::release, surgery::EventKind::fascia_cut,
        surgery::EventKind::strand_cut, surgery::EventKind::cautery_on,
        surgery::EventKind::cautery_off, surgery::EventKind::contact_begin,
        surgery::EventKind::contact_end, surgery::EventKind::injury,
        surgery::EventKind::cut_refused, surgery::EventKind::fragment_vaporised,
        surgery::EventKind::strand_torn, surgery::EventKind::device_lost,
        surgery::EventKind::device_restored}) {
    events[surgery::to_string(kind)] = s.events.count(kind);
  }
  out["events"] = events;
  out["fascia_edges_cut"] = s.fascia_edges_cut;
  out["strands_cut"] = s.strands_cut;
  out["strands_torn"] = s.strands_torn;
  out["cautery_energy_j"] = s.cautery_energy;
  std::size_t coagulated = 0, injured = 0;
  for (std::uint8_t c : s.cautery.coagulated)
    coagulated += c;
  for (std::uint8_t c : s.cautery.injured)
    injured += c;
  out["coagulated_particles"] = coagulated;
  out["ima_injured_particles"] = injured;
  const tissue::MeshObject& fascia = s.scene.patch.world.meshes[s.scene.patch.fascia];
  out["fascia_vertices"] = fascia.particle_count;
  out["fascia_triangles"] = fascia.triangles.size();
  out["held_particles"] = s.grasper.held.size();
  // The instruments' stops: their checks of the heart searched, and answered by what the last
  // search proved (session::ProbeClearance).
  std::uint64_t searched = 0, skipped = 0;
  for (const session::Station& st : s.stations) {
    searched += st.heart_probes.searched;
    skipped += st.heart_probes.skipped;
  }
  out["instrument_heart_checks"] = {{"searched", searched}, {"answered_by_bound", skipped}};
  nlohmann::ordered_json warnings = nlohmann::ordered_json::object();
  warnings["cuts_refused"] = s.refused_cuts;
  warnings["missed_tool_contacts"] = s.missed_tool_contacts;
  out["warnings"] = warnings;
}

}  // namespace imasim::cli
