#pragma once
// The session's events as CSV (time_s,kind,instrument,tissue,count,value), written while the
// session runs: each step appends the events it added, and the file is flushed at least once a
// second, so an interrupted or killed run keeps what happened up to then.
#include <cstddef>
#include <string>

#include "metrics/output_file.hpp"
#include "surgery/events.hpp"

namespace imasim::metrics {

inline constexpr const char* kEventCsvHeader = "time_s,kind,instrument,tissue,count,value\n";

// One CSV line, with its newline.
std::string event_csv_line(const surgery::Event& event);

class EventCsvWriter {
 public:
  // Writes the header at once (and flushes it, so even an empty run leaves a valid file).
  explicit EventCsvWriter(OutputFile file);

  // Appends the events of `log` not written yet, flushing when a second has passed.
  void append_new(const surgery::EventLog& log);
  // Appends what is left and closes the file, checking that everything reached it.
  void finish(const surgery::EventLog& log);

  std::size_t written() const { return written_; }
  const std::string& path() const { return file_.path(); }

 private:
  OutputFile file_;
  std::size_t written_ = 0;
};

}  // namespace imasim::metrics
