// Robustness: random anchor sets on genus 0, 1, 2 (capped here; bench/ runs hundreds), and
// determinism across runs and thread counts.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "cbd/anchor_sampling.h"
#include "cbd/pipeline.h"
#include "support/fixtures.h"
#include "support/stress.h"

using namespace cbd;

// One test per genus and seed: each is a full pipeline run per anchor set, and under the
// sanitizers one genus's three seeds together come near one test's timeout. Instantiated as
// LongRuns/...: a minute and more in all, so they carry the ctest label slow (tests/CMakeLists.txt).
class StressGenus : public ::testing::TestWithParam<std::tuple<int, unsigned>> {};

TEST_P(StressGenus, RandomAnchorsEitherSucceedWithAllInvariantsOrFailTyped) {
  const auto [genus, seed] = GetParam();
  const stress::SyntheticPair pair = stress::makePair(genus);
  int ok = 0, runs = 0;
  for (int count : {4 + 2 * genus, 9, 17, 33}) {
    for (bool farthest : {true, false}) {
      SCOPED_TRACE(pair.name + ", " + std::to_string(count) + " anchors, seed " + std::to_string(seed) +
                   (farthest ? " farthest" : " random"));
      const auto sa = stress::randomAnchors(pair.source, count, seed * 7919u + count, farthest);
      const stress::Outcome o = stress::run(pair, sa);
      ++runs;
      if (o.code == ErrorCode::AnchorsShareVertex) continue;  // the synthetic transfer merged two
      if (o.ok) {
        ++ok;
        EXPECT_TRUE(o.invariantsHold);
      } else {
        // A clear, typed failure and nothing else.
        EXPECT_TRUE(o.code == ErrorCode::LayoutFailed || o.code == ErrorCode::TooFewAnchors) << o.message;
        EXPECT_FALSE(o.message.empty());
      }
    }
  }
  RecordProperty("success_genus_" + std::to_string(genus) + "_seed_" + std::to_string(seed),
                 std::to_string(ok) + "/" + std::to_string(runs));
  // Well-spread (farthest-point) anchor sets of moderate size must work on every genus.
  EXPECT_GT(ok, runs / 3) << pair.name;
}

INSTANTIATE_TEST_SUITE_P(LongRuns, StressGenus, ::testing::Combine(::testing::Values(0, 1, 2), ::testing::Values(1u, 2u, 3u)),
                         [](const ::testing::TestParamInfo<StressGenus::ParamType>& info) {
                           return "genus" + std::to_string(std::get<0>(info.param)) + "_seed" +
                                  std::to_string(std::get<1>(info.param));
                         });

TEST(Determinism, SameInputSameOutputAcrossRunsAndThreadCounts) {
  const stress::SyntheticPair pair = stress::makePair(0);
  const auto sa = farthestPointSampling(pair.source, 20);
  std::vector<int> ta;
  for (int v : sa) ta.push_back(pair.targetOf[v]);
  CrossParameterizationOptions one, two;
  one.parameterization.threads = 1;
  two.parameterization.threads = 2;
  // Two runs, on one thread and on two: a result that hung on the threads' timing would differ
  // between them as it would between two runs on two threads.
  const auto a = crossParameterize(pair.source, sa, pair.target, ta, 2, one);
  const auto b = crossParameterize(pair.source, sa, pair.target, ta, 2, two);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  ASSERT_EQ(b.map.sourceImage.size(), a.map.sourceImage.size());
  for (size_t v = 0; v < a.map.sourceImage.size(); ++v) {
    EXPECT_EQ(b.map.sourceImage[v], a.map.sourceImage[v]);  // bit for bit
    EXPECT_EQ(b.map.sourceToTarget[v].face, a.map.sourceToTarget[v].face);
  }
  ASSERT_EQ(b.layouts.source.edges.size(), a.layouts.source.edges.size());
  for (size_t e = 0; e < a.layouts.source.edges.size(); ++e) {
    EXPECT_EQ(b.layouts.source.edges[e].vertices, a.layouts.source.edges[e].vertices);
    EXPECT_EQ(b.layouts.target.edges[e].vertices, a.layouts.target.edges[e].vertices);
  }
  EXPECT_EQ(b.metrics.eL2, a.metrics.eL2);
}

TEST(Stress, AnchorsCrowdedInOneSmallRegion) {
  // Ten anchors packed within a small cap of the sphere, the rest of the surface empty: the
  // method must still give valid layouts and a bijective map, or a typed error.
  const stress::SyntheticPair pair = stress::makePair(0);
  std::vector<int> sa;
  for (int v = 0; v < pair.source.vertexCount() && sa.size() < 10; ++v)
    if ((pair.source.positions[v] - Vec3(0, 0, 1)).norm() < 0.35) sa.push_back(v);
  ASSERT_EQ(sa.size(), 10u);
  const stress::Outcome o = stress::run(pair, sa);
  if (o.ok) {
    EXPECT_TRUE(o.invariantsHold);
  } else {
    EXPECT_EQ(o.code, ErrorCode::LayoutFailed) << o.message;
  }
  RecordProperty("crowded_status", errorCodeName(o.code));
}
