#include "cbd/progress.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <thread>

namespace cbd {

struct Progress::Shared {
  ProgressCallback callback;
  std::thread::id owner = std::this_thread::get_id();
  std::atomic<bool> cancelled{false};
  std::mutex mutex;
  int shown = -1;        ///< the last percentage passed to the callback
  int highest = 0;       ///< the highest percentage reported by any thread
  std::string stage;     ///< the stage of that report
  std::chrono::steady_clock::time_point lastCall{};
};

Progress::Progress(ProgressCallback callback) : shared_(std::make_shared<Shared>()) {
  shared_->callback = std::move(callback);
}

bool Progress::cancelled() const { return shared_ && shared_->cancelled.load(std::memory_order_relaxed); }

bool Progress::report(double fraction, const char* stage) const {
  if (!shared_) return true;
  Shared& s = *shared_;
  if (s.cancelled.load(std::memory_order_relaxed)) return false;
  if (!s.callback || quiet_) return true;
  const double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  const int percent = std::clamp(static_cast<int>(std::lround(from_ + f * (to_ - from_))), 0, 100);
  int show = 0;
  std::string text;
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    if (percent >= s.highest) {
      s.highest = percent;
      s.stage = stage ? stage : "";
    }
    // Only the creating thread calls back (a GUI's widgets live there).
    if (std::this_thread::get_id() != s.owner) return true;
    const auto now = std::chrono::steady_clock::now();
    if (s.highest == s.shown && now - s.lastCall < kProgressInterval) return true;
    s.shown = show = s.highest;
    s.lastCall = now;
    text = s.stage;
  }
  // Outside the lock: the callback may take long (a GUI processes its events in it).
  if (!s.callback(show, text.c_str())) s.cancelled.store(true, std::memory_order_relaxed);
  return !s.cancelled.load(std::memory_order_relaxed);
}

Progress Progress::quiet() const {
  Progress p = *this;
  p.quiet_ = true;
  return p;
}

Progress Progress::part(double a, double b) const {
  Progress p = *this;
  p.from_ = from_ + std::clamp(a, 0.0, 1.0) * (to_ - from_);
  p.to_ = from_ + std::clamp(b, 0.0, 1.0) * (to_ - from_);
  return p;
}

}  // namespace cbd
