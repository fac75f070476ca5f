#include "metrics/event_csv.hpp"

#include <cstdio>
#include <utility>

namespace imasim::metrics {

std::string event_csv_line(const surgery::Event& e) {
  char line[160];
  const int n = std::snprintf(line, sizeof line, "%.4f,%s,%s,%s,%u,%.6g\n", e.time,
                              surgery::to_string(e.kind), e.instrument == 0 ? "left" : "right",
                              surgery::to_string(e.tissue), e.count, double(e.value));
  return std::string(line, n > 0 ? std::size_t(n) : 0);
}

EventCsvWriter::EventCsvWriter(OutputFile file) : file_(std::move(file)) {
  file_.write(kEventCsvHeader);
  file_.flush();
}

void EventCsvWriter::append_new(const surgery::EventLog& log) {
  for (; written_ < log.events.size(); ++written_)
    file_.write(event_csv_line(log.events[written_]));
  file_.flush_if_due();
}

void EventCsvWriter::finish(const surgery::EventLog& log) {
  append_new(log);
  file_.close();
}

}  // namespace imasim::metrics
