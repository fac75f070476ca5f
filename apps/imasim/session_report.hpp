#pragma once
// What `run --script` adds to the report: the session's totals and events.
#include <nlohmann/json.hpp>
#include <ostream>

#include "session/surgical_session.hpp"

namespace imasim::cli {

// Event counts by kind, cut totals, cautery energy, injured IMA particles, tool poses.
void add_session_report(nlohmann::ordered_json& out, const session::SurgicalSession& session);

// One line per event: time_s,kind,instrument,tissue,count,value.
void write_events_csv(std::ostream& out, const surgery::EventLog& log);

}  // namespace imasim::cli
