#include "study_progress.hpp"

#include <unistd.h>

#include <ostream>

#include "report/text_format.hpp"

namespace imasim::cli {

namespace {

bool same(const TrialCounts& a, const TrialCounts& b) {
  return a.finished == b.finished && a.failed == b.failed && a.running == b.running &&
         a.total == b.total;
}

}  // namespace

std::string progress_line(const TrialCounts& c, double elapsed_s, std::size_t bar_width) {
  const std::size_t filled = c.total == 0 ? bar_width : bar_width * c.finished / c.total;
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string line = "[";
  line.append(filled, '#').append(bar_width - filled, '.').append("] ");
  line.append(std::to_string(c.finished)).append("/").append(std::to_string(c.total));
  line.append(" done  ").append(std::to_string(c.failed)).append(" failed  ");
  line.append(std::to_string(c.running)).append(" running  ");
  line.append(report::clock_text(elapsed_s)).append(" elapsed");
  // Trials run in waves of about the same length: the time per finished trial so far times those
  // left is the estimate (none before the first ends).
  if (c.finished > 0 && c.finished < c.total)
    line.append("  ~")
        .append(report::clock_text(elapsed_s / double(c.finished) * double(c.total - c.finished)))
        .append(" left");
  return line;
}

StudyProgress::StudyProgress(bool show, std::ostream& out)
    : show_(show), terminal_(::isatty(STDERR_FILENO) == 1), out_(out), start_(Clock::now()) {
  show_ = show_ || terminal_;
}

void StudyProgress::update(const TrialCounts& counts) {
  if (!show_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (terminal_) {
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(200) && same(counts, last_)) return;
    out_ << '\r' << progress_line(counts, elapsed, 24) << "\x1b[K" << std::flush;
  } else {
    if (drawn_ && same(counts, last_)) return;
    out_ << "imasim study: " << progress_line(counts, elapsed, 24) << '\n' << std::flush;
  }
  drawn_ = true;
  last_draw_ = now;
  last_ = counts;
}

void StudyProgress::finish() {
  if (show_ && terminal_ && drawn_) out_ << '\n' << std::flush;
}

}  // namespace imasim::cli
