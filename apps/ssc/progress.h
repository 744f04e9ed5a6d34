// Progress of a study's trials on stderr: a bar redrawn in place on a terminal; when stderr is
// a pipe or a file (batch jobs, logs), one line each time another kLinePercent of the trials is
// done, so a long run shows that it is alive without flooding the log.
#ifndef SSC_APPS_SSC_PROGRESS_H_
#define SSC_APPS_SSC_PROGRESS_H_

#include <unistd.h>

#include <cstdio>
#include <string>

#include "studies/sweep.h"

namespace ssc {

class TrialProgress {
 public:
  static constexpr int kLinePercent = 5;

  // `enabled`: false for --no-progress and for ranks other than 0.
  TrialProgress(const char* command, bool enabled)
      : command_(command), enabled_(enabled), terminal_(isatty(STDERR_FILENO) != 0) {}

  void operator()(const SweepProgress& s) {
    if (!enabled_ || s.total <= 0) return;
    const int ran = s.done - s.skipped;
    const double rate = s.elapsed_s > 0 ? ran / s.elapsed_s : 0;
    const double eta = rate > 0 ? (s.total - s.done) / rate : 0;
    if (terminal_) {
      const int width = 30, filled = width * s.done / s.total;
      std::fprintf(stderr, "\r[%.*s%*s] %d/%d trials  %.1f trials/s  ETA %.0f s ", filled,
                   "##############################", width - filled, "", s.done, s.total, rate,
                   eta);
      std::fflush(stderr);
      drew_bar_ = true;
      return;
    }
    const int percent = 100 * s.done / s.total;
    if (percent < next_percent_ && s.done < s.total) return;
    next_percent_ = (percent / kLinePercent + 1) * kLinePercent;
    std::fprintf(stderr, "%s: %d/%d trials (%d %%), %.1f trials/s, %.0f s, ETA %.0f s\n",
                 command_.c_str(), s.done, s.total, percent, rate, s.elapsed_s, eta);
    std::fflush(stderr);
  }

  // Ends the bar's line (nothing for the line log).
  void Finish() {
    if (drew_bar_) std::fprintf(stderr, "\n");
  }

 private:
  std::string command_;
  bool enabled_, terminal_;
  bool drew_bar_ = false;
  int next_percent_ = 0;
};

}  // namespace ssc

#endif  // SSC_APPS_SSC_PROGRESS_H_
