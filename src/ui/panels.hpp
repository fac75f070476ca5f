#pragma once
// The window's Dear ImGui panels: the session (time, heart, pause, restart, record,
// end, camera and stereo), the instruments (jaws, clutch, contact, pedal, power), the force
// readout per channel with its history, the live metrics, the help and the score card. They
// only read what the physics thread published and say which commands were clicked; the window
// carries those out as it does a key's.
#include <optional>
#include <vector>

#include "ui/key_bindings.hpp"
#include "ui/live_numbers.hpp"
#include "ui/session_score.hpp"
#include "ui/view_state.hpp"

namespace imasim::ui {

// The width of the panels' column on the right of the window (unit: pixels).
inline constexpr int kPanelWidth = 360;

// Inside an ImGui frame. `clicked` receives the commands of the buttons pressed.
void draw_panels(const LiveNumbers& numbers, const std::optional<ScoreCard>& card, ViewState& view,
                 int window_width, int window_height, std::vector<Command>& clicked);

}  // namespace imasim::ui
