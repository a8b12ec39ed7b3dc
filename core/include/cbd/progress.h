#pragma once
/// @file progress.h
/// Progress and cancellation of long stages: one callback, called with the percentage of the
/// whole run done so far and a short stage name a user understands; returning false cancels the
/// run, which then ends with ErrorCode::Cancelled and writes nothing.

#include <algorithm>
#include <cmath>
#include <functional>

namespace cbd {

/// `percent` in 0..100, never decreasing within one run; `stage` a few words ("mapping").
using ProgressCallback = std::function<bool(int percent, const char* stage)>;

/// The share [from, to] of a run's percentages that one stage reports into: the stage reports
/// fractions 0..1 of its own work, the callback sees from + fraction * (to - from).
struct Progress {
  const ProgressCallback* callback = nullptr;
  int from = 0, to = 100;
  /// False when the user cancelled (the stage then stops and returns Cancelled).
  bool report(double fraction, const char* stage) const {
    if (!callback || !*callback) return true;
    const double f = std::clamp(fraction, 0.0, 1.0);
    return (*callback)(from + static_cast<int>(std::lround(f * (to - from))), stage);
  }
  /// The part [a, b] (fractions of this range) as a range of its own.
  Progress part(double a, double b) const {
    return {callback, from + static_cast<int>(std::lround(a * (to - from))),
            from + static_cast<int>(std::lround(b * (to - from)))};
  }
};

}  // namespace cbd
