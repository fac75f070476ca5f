#pragma once
// What `run --script` adds to the report: the session's totals and events.
#include <nlohmann/json.hpp>

#include "session/surgical_session.hpp"

namespace imasim::cli {

// Event counts by kind, cut totals, cautery energy, injured IMA particles, tool poses.
void add_session_report(nlohmann::ordered_json& out, const session::SurgicalSession& session);

}  // namespace imasim::cli
