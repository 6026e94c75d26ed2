#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <string>

namespace sph::cli {

namespace {

std::string formatSeconds(double s) {
  char text[32];
  if (s < 60.0) {
    std::snprintf(text, sizeof text, "%.0fs", s);
  } else {
    std::snprintf(text, sizeof text, "%dm%02ds", static_cast<int>(s / 60),
                  static_cast<int>(s) % 60);
  }
  return text;
}

}  // namespace

Progress::Progress(double endTime, bool enabled)
    : endTime_(endTime),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_) {}

void Progress::update(double simTime, std::uint64_t steps) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double sinceLast = std::chrono::duration<double>(now - lastPrint_).count();
  if (sinceLast < (terminal_ ? 0.2 : 5.0)) return;
  lastPrint_ = now;
  print(simTime, steps, false);
}

void Progress::finish(double simTime, std::uint64_t steps) {
  if (enabled_) print(simTime, steps, true);
}

void Progress::print(double simTime, std::uint64_t steps, bool final) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = endTime_ > 0.0 ? std::clamp(simTime / endTime_, 0.0, 1.0) : 1.0;
  const double stepsPerSecond = elapsed > 0.0 ? double(steps) / elapsed : 0.0;
  const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  char line[256];
  std::snprintf(line, sizeof line, "t = %.4g / %.4g s, %llu steps, %.0f steps/s, %s %s", simTime,
                endTime_, static_cast<unsigned long long>(steps), stepsPerSecond,
                final ? "took" : "left", formatSeconds(final ? elapsed : left).c_str());
  if (terminal_) {
    const int width = 30;
    const int filled = static_cast<int>(fraction * width);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(static_cast<std::size_t>(width), '-');
    std::fprintf(stderr, "\r[%s] %3.0f%% %s\033[K%s", bar.c_str(), fraction * 100.0, line,
                 final ? "\n" : "");
  } else {
    std::fprintf(stderr, "%3.0f%% %s\n", fraction * 100.0, line);
  }
  std::fflush(stderr);
}

}  // namespace sph::cli
