// Progress line drawing: carriage return and clear-to-end-of-line, at most ten times a second; progress lines.
#include "app/progress.hpp"

#include <unistd.h>
#include <cstdio>

namespace app {

ProgressLine::ProgressLine()
    : enabled_(::isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressLine::update(int done, int last) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < last && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  const int frames_done = done + 1;
  const double fps = elapsed_s > 0.0 ? frames_done / elapsed_s : 0.0;
  const double left_s = fps > 0.0 ? (last - done) / fps : 0.0;
  std::fprintf(stderr, "\rframe %d/%d  %.1f fps  %.1f s left\x1b[K", done, last, fps, left_s);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\x1b[K");
  std::fflush(stderr);
  drawn_ = false;
}

frames::Progress progress_lines() {
  return [](int done, int total) {
    std::fprintf(stdout, "progress %d %d\n", done, total);
    std::fflush(stdout);
  };
}

}  // namespace app
