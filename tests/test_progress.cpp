// Progress and cancellation (progress.h): percentages of the run, never decreasing; the callback
// only on the creating thread; cancellation sticky and shared by every copy.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cbd/progress.h"

using namespace cbd;

namespace {
struct Recorder {
  std::vector<std::pair<int, std::string>> calls;
  int stopAt = 101;  ///< return false from this percentage on
  ProgressCallback callback() {
    return [this](int percent, const char* stage) {
      calls.emplace_back(percent, stage);
      return percent < stopAt;
    };
  }
};
}  // namespace

TEST(Progress, ADefaultProgressReportsNowhereAndNeverCancels) {
  const Progress p;
  EXPECT_TRUE(p.report(0.5, "x"));
  EXPECT_FALSE(p.cancelled());
  EXPECT_TRUE(p.part(0.2, 0.4).report(1.0, "x"));
}

TEST(Progress, PartsMapTheirFractionsIntoTheRunsPercentages) {
  Recorder r;
  const Progress run(r.callback());
  const Progress stage = run.part(0.2, 0.6);     // 20..60 %
  const Progress sub = stage.part(0.5, 1.0);     // 40..60 %
  stage.report(0.0, "a");
  stage.report(0.5, "b");
  sub.report(0.5, "c");
  sub.report(1.0, "d");
  ASSERT_EQ(r.calls.size(), 4u);
  EXPECT_EQ(r.calls[0], std::make_pair(20, std::string("a")));
  EXPECT_EQ(r.calls[1], std::make_pair(40, std::string("b")));
  EXPECT_EQ(r.calls[2], std::make_pair(50, std::string("c")));
  EXPECT_EQ(r.calls[3], std::make_pair(60, std::string("d")));
}

TEST(Progress, PercentagesNeverDecreaseAndAreClamped) {
  Recorder r;
  const Progress run(r.callback());
  run.report(0.7, "late");
  run.part(0.0, 0.5).report(0.2, "early");  // 10 %: shown as the 70 % already reached
  run.report(5.0, "beyond");
  run.report(-3.0, "before");
  for (size_t k = 1; k < r.calls.size(); ++k) EXPECT_GE(r.calls[k].first, r.calls[k - 1].first);
  for (const auto& c : r.calls) {
    EXPECT_GE(c.first, 0);
    EXPECT_LE(c.first, 100);
  }
  EXPECT_EQ(r.calls.back().first, 100);
}

TEST(Progress, TheSamePercentageIsNotRepeatedWithinTheInterval) {
  Recorder r;
  const Progress run(r.callback());
  for (int k = 0; k < 1000; ++k) run.report(0.5, "same");
  EXPECT_EQ(r.calls.size(), 1u);
  std::this_thread::sleep_for(kProgressInterval + std::chrono::milliseconds(20));
  run.report(0.5, "same");  // a heartbeat after the interval (lets a GUI stay responsive)
  EXPECT_EQ(r.calls.size(), 2u);
}

TEST(Progress, ReturningFalseCancelsEveryCopyForGood) {
  Recorder r;
  r.stopAt = 30;
  const Progress run(r.callback());
  const Progress a = run.part(0.0, 0.5), b = run.part(0.5, 1.0);
  EXPECT_TRUE(a.report(0.2, "x"));   // 10 %
  EXPECT_FALSE(a.report(0.8, "x"));  // 40 %: the callback says stop
  EXPECT_TRUE(run.cancelled());
  EXPECT_TRUE(b.cancelled());
  const size_t calls = r.calls.size();
  EXPECT_FALSE(b.report(0.9, "y"));
  EXPECT_FALSE(run.quiet().report(0.1, "z"));
  EXPECT_EQ(r.calls.size(), calls) << "no callback after cancelling";
}

TEST(Progress, OtherThreadsNeverCallBackButSeeTheCancel) {
  Recorder r;
  r.stopAt = 50;
  const std::thread::id owner = std::this_thread::get_id();
  std::vector<std::thread::id> callers;
  const Progress run(ProgressCallback([&](int percent, const char* stage) {
    callers.push_back(std::this_thread::get_id());
    return r.callback()(percent, stage);
  }));
  std::thread worker([&] { run.report(0.4, "from a worker"); });
  worker.join();
  EXPECT_TRUE(callers.empty());
  // The owner's next report shows what the worker reached.
  run.report(0.1, "owner");
  ASSERT_EQ(r.calls.size(), 1u);
  EXPECT_EQ(r.calls[0].first, 40);
  EXPECT_EQ(r.calls[0].second, "from a worker");
  EXPECT_FALSE(run.report(0.6, "owner"));
  bool workerSawCancel = false;
  std::thread late([&] { workerSawCancel = !run.report(0.7, "w") && run.cancelled(); });
  late.join();
  EXPECT_TRUE(workerSawCancel);
  for (const auto& id : callers) EXPECT_EQ(id, owner);
}

TEST(Progress, AQuietCopyDoesNotMoveTheBar) {
  Recorder r;
  const Progress run(r.callback());
  run.quiet().report(0.9, "quiet");
  EXPECT_TRUE(r.calls.empty());
  run.report(0.1, "loud");
  ASSERT_EQ(r.calls.size(), 1u);
  EXPECT_EQ(r.calls[0].first, 10);
}
