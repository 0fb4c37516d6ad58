#pragma once
// Progress line on stderr for long runs, shown only when stderr is a terminal.
#include <unistd.h>

#include <cstdio>
#include <string>

namespace lac::io {

class Progress {
 public:
  Progress(std::string label, size_t total) : label_(std::move(label)), total_(total), enabled_(isatty(2) != 0) {}
  ~Progress() {
    if (enabled_ && shown_) std::fprintf(stderr, "\n");
  }
  void tick(size_t done) {
    if (!enabled_ || total_ == 0) return;
    const size_t percent = done * 100 / total_;
    if (percent == last_ && done != total_) return;
    last_ = percent;
    shown_ = true;
    std::fprintf(stderr, "\r%s: %zu/%zu (%zu%%)", label_.c_str(), done, total_, percent);
    std::fflush(stderr);
  }

 private:
  std::string label_;
  size_t total_;
  bool enabled_;
  bool shown_ = false;
  size_t last_ = 101;
};

}  // namespace lac::io
