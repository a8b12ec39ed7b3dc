#pragma once
/// @file progress.h
/// Progress and cancellation of long stages. Contract:
///  * one callback, `bool(int percent, const char* stage)`, called with the percentage of the
///    whole run done so far (never decreasing) and a few words a user understands;
///  * it is called only on the thread that created the `Progress` (a GUI's progress bar must not
///    be touched from a worker thread), at most every `kProgressInterval` unless the percentage
///    changes; stages that run a second thread report from it too, and those reports are shown
///    by the next report of the creating thread;
///  * returning false cancels: every later `report` on any thread returns false, and the stage
///    that sees it stops and returns ErrorCode::Cancelled; front ends then write nothing.
/// A default-constructed `Progress` reports nowhere and never cancels.

#include <chrono>
#include <functional>
#include <memory>

namespace cbd {

/// `percent` in 0..100; return false to cancel the run.
using ProgressCallback = std::function<bool(int percent, const char* stage)>;

/// The shortest time between two calls of the callback with the same percentage.
inline constexpr std::chrono::milliseconds kProgressInterval{100};

/// A stage's view of the run's progress: the share [from, to] of the run's percentages that the
/// stage reports into, as fractions 0..1 of its own work. Cheap to copy; copies share the
/// callback and the cancelled state.
class Progress {
 public:
  Progress() = default;
  /// Reports into (a copy of) `callback`; an empty callback reports nowhere but can still be
  /// asked whether another copy was cancelled.
  Progress(ProgressCallback callback);  // NOLINT: implicit, so a lambda can be passed directly

  /// Fraction `fraction` of this stage done; false once the run is cancelled.
  bool report(double fraction, const char* stage) const;
  /// Whether the run was cancelled (any thread may ask).
  bool cancelled() const;
  /// The part [a, b] (fractions of this range) as a range of its own.
  Progress part(double a, double b) const;
  /// The same run, but its reports do not move the bar: for a second thread doing the same
  /// stage on the other surface alongside, so that the bar follows one of them, steadily.
  Progress quiet() const;

 private:
  struct Shared;
  std::shared_ptr<Shared> shared_;
  double from_ = 0.0, to_ = 100.0;
  bool quiet_ = false;
};

}  // namespace cbd
