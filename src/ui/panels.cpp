#include "ui/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ui/peak_envelope.hpp"

namespace imasim::ui {

namespace {

constexpr std::array<const char*, 2> kTools = {"Forceps (left)", "Hook (right)"};
constexpr std::array<const char*, 3> kChannels = {"normal", "tangential", "thermal"};
constexpr float kGap = 6;                         // between stacked panels (unit: pixels)
const ImVec4 kWarning(1.0f, 0.75f, 0.25f, 1.0f);  // what needs the user's eye (amber)

double degrees(Real rad) {
  return double(rad) * 180.0 / std::numbers::pi;
}

const char* pedal_name(surgery::PedalMode m) {
  return m == surgery::PedalMode::cut ? "CUT" : m == surgery::PedalMode::coag ? "COAG" : "off";
}

// A panel of the right-hand column, stacked below the previous one.
bool begin_column_panel(const char* title, float x, float& y, float height) {
  ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(float(kPanelWidth), height), ImGuiCond_Always);
  y += height + kGap;
  // No background of their own: the column is cleared to the panels' colour before the frame
  // (window_app.cpp). ImGui blends a textured background over the whole column otherwise, and on
  // Mesa's software rasteriser that cost about a tenth of the window's frame (docs/PERFORMANCE.md).
  return ImGui::Begin(title, nullptr,
                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                          ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoBackground);
}

void button(const char* label, Command command, std::vector<Command>& clicked) {
  if (ImGui::Button(label)) clicked.push_back(command);
}

void session_panel(const LiveNumbers& n, ViewState& view, std::vector<Command>& clicked) {
  ImGui::Text("%s  t = %.2f s  (%.2fx real time)", to_string(n.state), n.time_s, n.realtime_factor);
  ImGui::Text("step %.2f ms, %llu steps", n.step_ms, static_cast<unsigned long long>(n.steps));
  bool beating = n.beating_next;
  if (ImGui::Checkbox("Dynamic heart (restarts)", &beating)) clicked.push_back(Command::heart);
  ImGui::SameLine();
  ImGui::Text("%.0f bpm", double(n.heart_rate_bpm));
  ImGui::Text("heart: %s, phase %.2f", n.beating ? "beating" : "static", double(n.heart_phase));
  button(n.state == SimState::paused ? "Resume" : "Pause", Command::pause, clicked);
  ImGui::SameLine();
  button("Restart", Command::restart, clicked);
  ImGui::SameLine();
  button(n.recording ? "Stop recording" : "Record", Command::record, clicked);
  ImGui::SameLine();
  button("End", Command::end_session, clicked);
  if (ImGui::RadioButton("Endoscope", !view.orbit) && view.orbit)
    clicked.push_back(Command::camera);
  ImGui::SameLine();
  if (ImGui::RadioButton("Orbit", view.orbit) && !view.orbit) clicked.push_back(Command::camera);
  ImGui::SameLine();
  bool angled = n.optics_rad > Real(0.01);
  if (ImGui::Checkbox("30 deg optics", &angled)) clicked.push_back(Command::optics);
  ImGui::Text("stereo: %s", stereo_name(view.stereo));
  ImGui::SameLine();
  button("Stereo", Command::stereo, clicked);
  ImGui::SameLine();
  button("Help", Command::help, clicked);
  if (n.recording)
    ImGui::Text("recording: %llu rows", static_cast<unsigned long long>(n.recorded_rows));
  if (n.message[0] != '\0') ImGui::TextWrapped("%s", n.message.data());
}

void instruments_panel(const LiveNumbers& n) {
  for (std::size_t k = 0; k < 2; ++k) {
    const HandNumbers& h = n.hands[k];
    ImGui::Text("%s: jaws %.1f deg%s", kTools[k], degrees(h.jaw_angle_rad),
                h.clutch ? "  CLUTCH" : "");
    if (h.device_lost)
      ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.25f, 1.0f),
                         "   DEVICE LOST: held still, cautery off until it is back");
    ImGui::Text("   touching %s%s%s", surgery::to_string(h.contact),
                h.blocked_by_heart ? ", stopped by the heart" : "",
                h.blocked_by_wall ? ", stopped by the wall" : "");
  }
  ImGui::Text("Pedal: %s   power %.0f W", pedal_name(n.pedal), double(n.power_w));
}

void forces_panel(const LiveNumbers& n) {
  for (std::size_t k = 0; k < 2; ++k) {
    const HandNumbers& h = n.hands[k];
    ImGui::Text("%s  N %.2f  T %.2f  heat %.2f N", kTools[k], double(h.force_normal),
                double(h.force_tangential), double(h.force_thermal));
    for (std::size_t c = 0; c < 3; ++c) {
      ImGui::PushID(int(3 * k + c));
      // eq. 17's bound is 5 N, eq. 18's 2 N: one scale for all keeps them comparable.
      const auto peaks = peak_envelope<4>(h.history[c]);
      ImGui::PlotLines("", peaks.data(), int(peaks.size()), 0, kChannels[c], 0.0f, 5.0f,
                       ImVec2(float(kPanelWidth) - 20, 22));
      ImGui::PopID();
    }
  }
}

// The live devices: their peers, what they refused by reason and by sender's name, and how long
// each part was held for a lost device (nothing is refused in silence).
static void devices_lines(const console::DeviceTally& t) {
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  const devices::DeviceCounts& c = t.counts;
  if (c.peers_seen > 0)
    ImGui::Text("device peers: %llu now, %llu seen, %llu dropped, %llu turned away",
                u(c.peers_connected), u(c.peers_seen), u(c.peers_dropped), u(c.peers_turned_away));
  if (c.refused_total() > 0) {
    ImGui::TextColored(kWarning, "device messages refused %llu:", u(c.refused_total()));
    for (std::size_t r = 0; r < c.refused_by_reason.size(); ++r)
      if (c.refused_by_reason[r] > 0)
        ImGui::TextColored(
            kWarning, "  %s %llu: %s", devices::igtl_refusal_name(devices::IgtlRefusal(r)),
            u(c.refused_by_reason[r]), devices::igtl_refusal_meaning(devices::IgtlRefusal(r)));
    for (std::size_t k = 0; k < c.named; ++k)
      ImGui::TextColored(kWarning, "  from \"%s\" %llu", c.refused_names[k].name.data(),
                         u(c.refused_names[k].count));
    if (c.refused_others > 0)
      ImGui::TextColored(kWarning, "  from other names %llu", u(c.refused_others));
  }
  static constexpr const char* kPartNames[] = {"left hand", "right hand", "pedal"};
  for (std::size_t p = 0; p < t.losses.size(); ++p)
    if (t.losses[p].losses > 0)
      ImGui::TextColored(kWarning, "%s lost %llu time(s), %.2f s held%s", kPartNames[p],
                         u(t.losses[p].losses), t.losses[p].lost_s,
                         t.losses[p].held ? " (now)" : "");
}

void metrics_panel(const LiveNumbers& n) {
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  ImGui::Text("events %llu, grasps %llu, devices lost %llu", u(n.events), u(n.grasps),
              u(n.devices_lost));
  if (n.has_device_tally)
    devices_lines(n.device_tally);
  else if (n.device_refusals > 0)
    ImGui::TextColored(kWarning, "device messages refused %llu", u(n.device_refusals));
  ImGui::Text("fascia edges cut %llu, strands cut %llu / %llu", u(n.fascia_edges_cut),
              u(n.strands_cut), u(n.strands_total));
  ImGui::Text("strands torn %llu", u(n.strands_torn));
  ImGui::Text("IMA injuries %llu", u(n.ima_injuries));
  ImGui::Text("touches: heart %llu, chest wall %llu, IMA %llu",
              u(n.contacts_begun[std::size_t(surgery::Tissue::heart)]),
              u(n.contacts_begun[std::size_t(surgery::Tissue::chest_wall)]),
              u(n.contacts_begun[std::size_t(surgery::Tissue::ima)]));
  ImGui::Text("instrument collisions %u, heart contacts now %u", n.instrument_collisions,
              n.heart_contacts);
  if (n.sai_available)
    ImGui::Text("SAI so far: forceps %+.2f, hook %+.2f", double(n.sai[0]), double(n.sai[1]));
  else
    ImGui::Text("SAI: not available for this scene");
}

void help_window(ViewState& view, int width, int height) {
  ImGui::SetNextWindowPos(ImVec2(20, 20), ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(
      ImVec2(std::min(560.0f, float(width) - 40), std::min(620.0f, float(height) - 40)),
      ImGuiCond_Appearing);
  if (ImGui::Begin("Controls (F1)", &view.show_help, ImGuiWindowFlags_NoSavedSettings)) {
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, 60);
      ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
      for (const KeyBinding& b : key_bindings()) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.key_name);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(b.meaning);
      }
      ImGui::EndTable();
    }
    ImGui::TextWrapped(
        "Mouse: left drag orbits the camera, the wheel zooms (orbit camera). Right drag moves the "
        "right hand, with Shift in depth; middle drag moves the left hand. Tab hides the "
        "panels. Hands move the instruments through the arms' 3:1 motion scaling; hold a "
        "clutch to move a hand without its instrument.");
  }
  ImGui::End();
}

void score_window(const ScoreCard& c, ViewState& view, int width, std::vector<Command>& clicked) {
  ImGui::SetNextWindowPos(ImVec2(std::max(20.0f, float(width - kPanelWidth) / 2 - 260), 60),
                          ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(520, 560), ImGuiCond_Appearing);
  if (ImGui::Begin("Score card", &view.show_score, ImGuiWindowFlags_NoSavedSettings)) {
    const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    ImGui::Text("%s heart, %.1f s", c.beating ? "dynamic" : "static", c.duration_s);
    ImGui::Text("strands cut %llu of %llu, torn %llu; fascia edges cut %llu", u(c.strands_cut),
                u(c.strands_total), u(c.strands_torn), u(c.fascia_edges_cut));
    ImGui::Text("IMA injuries %llu (%llu particles)", u(c.ima_injuries),
                u(c.ima_injured_particles));
    ImGui::Text("collisions: instruments %d, heart touches %llu, chest wall %llu, IMA %llu",
                c.instrument_collisions, u(c.heart_touches), u(c.wall_touches), u(c.ima_touches));
    if (c.sai_available)
      ImGui::Text("SAI: forceps %+.2f, hook %+.2f (positive: away from the heart)",
                  double(c.sai[0]), double(c.sai[1]));
    if (!c.metrics.empty()) {
      ImGui::Text("metrics passed: %zu of %zu", c.passed, c.metrics.size());
      if (ImGui::BeginTable(
              "metrics", 4,
              ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit,
              ImVec2(0, 320))) {
        // Fixed widths: auto-fitted columns take a frame to size, and a screenshot may be it.
        ImGui::TableSetupColumn("metric", ImGuiTableColumnFlags_WidthFixed, 200);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthFixed, 120);
        ImGui::TableSetupColumn("threshold", ImGuiTableColumnFlags_WidthFixed, 90);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed, 40);
        ImGui::TableHeadersRow();
        for (const metrics::TraineeMetric& m : c.metrics) {
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(m.name.c_str());
          ImGui::TableNextColumn();
          ImGui::Text("%.3g %s", m.value, m.unit == "1" ? "" : m.unit.c_str());  // counts
          ImGui::TableNextColumn();
          ImGui::Text("%s %.3g", m.higher_is_better ? ">=" : "<=", m.threshold);
          ImGui::TableNextColumn();
          ImGui::TextColored(m.pass ? ImVec4(0.4f, 1, 0.4f, 1) : ImVec4(1, 0.4f, 0.4f, 1), "%s",
                             m.pass ? "pass" : "fail");
        }
        ImGui::EndTable();
      }
    }
    button("New session", Command::restart, clicked);
  }
  ImGui::End();
}

}  // namespace

void draw_panels(const LiveNumbers& n, const std::optional<ScoreCard>& card, ViewState& view,
                 int width, int height, std::vector<Command>& clicked) {
  if (view.show_panels) {
    const float x = float(width - kPanelWidth);
    float y = 0;
    if (begin_column_panel("Session", x, y, 200)) session_panel(n, view, clicked);
    ImGui::End();
    if (begin_column_panel("Instruments", x, y, 126)) instruments_panel(n);
    ImGui::End();
    if (begin_column_panel("Forces (N)", x, y, 230)) forces_panel(n);
    ImGui::End();
    if (begin_column_panel("Metrics", x, y, std::max(60.0f, float(height) - y))) metrics_panel(n);
    ImGui::End();
  }
  if (view.show_help) help_window(view, width, height);
  if (view.show_score && card) score_window(*card, view, width, clicked);
}

}  // namespace imasim::ui
