// Reports (report.h): the JSON keys scripts read, the lines both front ends show, the summary.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cbd/anchor_sampling.h"
#include "cbd/report.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;

namespace {
/// A sphere onto an ellipsoid, through the whole pipeline in memory.
CrossParameterizationResult sphereOntoEllipsoid(const CrossParameterizationOptions& o) {
  const IndexedMesh s = fx::icosphere(3);
  IndexedMesh t = s;
  for (Vec3& p : t.positions) p = p.cwiseProduct(Vec3(1.6, 1.0, 0.7));
  const std::vector<int> a = farthestPointSampling(s, 8);
  return crossParameterize(s, a, t, a, 2, o);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
}  // namespace

TEST(Report, MetricsAndTimesKeepTheirJsonKeys) {
  DistortionMetrics m;
  m.eAng = 0.25, m.eAngDegrees = 7.5, m.eL2 = 1.125, m.eL2Inverse = 1.5, m.flipped = 3, m.degenerate = 1;
  const Json j = toJson(m);
  EXPECT_DOUBLE_EQ(j.at("e_ang").get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(j.at("e_ang_deg").get<double>(), 7.5);
  EXPECT_DOUBLE_EQ(j.at("e_l2").get<double>(), 1.125);
  EXPECT_DOUBLE_EQ(j.at("e_l2_inverse").get<double>(), 1.5);
  EXPECT_EQ(j.at("flipped").get<int>(), 3);
  EXPECT_EQ(j.at("degenerate").get<int>(), 1);
  StageTimes t;
  t.untangle = 2.5, t.total = 3.0;
  const Json k = toJson(t);
  for (const char* key : {"voronoi", "source_layout", "target_layout", "straighten", "parameterization", "untangle",
                          "distortion", "total"})
    EXPECT_TRUE(k.contains(key)) << key;
  EXPECT_DOUBLE_EQ(k.at("untangle").get<double>(), 2.5);
}

TEST(Report, TheSummaryLineSaysHowGoodTheMapIs) {
  DistortionMetrics m;
  m.eAng = 0.17424, m.eAngDegrees = 11.456, m.eL2 = 1.23444, m.flipped = 1;
  EXPECT_EQ(summary(m, 3.3301), "E_ang 0.1742 (11.46 deg), E_L2 1.2344, 1 flipped triangle, 3.33 s");
  m.flipped = 0;
  EXPECT_NE(summary(m, 1).find("0 flipped triangles"), std::string::npos);
}

TEST(Report, AMapRunsLinesAndJsonAgree) {
  CrossParameterizationOptions o;
  const CrossParameterizationResult r = sphereOntoEllipsoid(o);
  ASSERT_TRUE(r.status) << r.status.message;
  const std::vector<std::string> layout = layoutLines(r.layouts);
  ASSERT_FALSE(layout.empty());
  EXPECT_TRUE(startsWith(layout[0], "layout  voronoi: 18 edges")) << layout[0];
  const std::vector<std::string> map = mapLines(r, o);
  bool metrics = false;
  for (const std::string& l : map) {
    const std::string label = l.substr(0, l.find(' '));
    EXPECT_TRUE(label == "straighten" || label == "smooth" || label == "map" || label == "composed" ||
                label == "untangle" || label == "optimize")
        << l;
    EXPECT_GE(l.find_first_not_of(' ', label.size()), 8u) << "the text starts at column eight or after: " << l;
    if (startsWith(l, "map     E_ang ")) {
      metrics = true;
      EXPECT_NE(l.find(fixed(r.metrics.eAng, 4)), std::string::npos) << l;
      EXPECT_NE(l.find(fixed(r.metrics.eL2, 4)), std::string::npos) << l;
    }
  }
  EXPECT_TRUE(metrics);
  const Json j = toJson(r.layouts);
  EXPECT_EQ(j.at("edges").get<int>(), 18);
  EXPECT_EQ(j.at("patches").get<int>(), 12);
  EXPECT_EQ(j.at("diagram").get<std::string>(), "source");
  EXPECT_TRUE(j.contains("target"));
  EXPECT_TRUE(startsWith(timesLine(r.times, true), "time    voronoi "));
  EXPECT_NE(timesLine(r.times, true).find("untangle"), std::string::npos);
  EXPECT_EQ(timesLine(r.times, false).find("untangle"), std::string::npos);
}

TEST(Report, AJobThatStoppedEarlyReportsOnlyWhatItReached) {
  MapJob job;
  job.pipeline.method = LayoutMethod::Greedy;
  MapJobResult r;  // nothing computed
  const Json j = mapJobJson(job, r);
  EXPECT_EQ(j.at("method").get<std::string>(), "greedy");
  EXPECT_TRUE(j.contains("source"));
  EXPECT_FALSE(j.contains("timing_s"));
  EXPECT_FALSE(j.contains("metrics"));
  EXPECT_FALSE(j.at("source").contains("anchors"));
}

TEST(Report, CheckListsEveryAnchorWithItsSnap) {
  InputReport r;
  r.anchors.names = {"nose", "tail"};
  r.anchors.source = {{"nose", 4, 0.01}, {"tail", 9, 0.0}};
  r.anchors.target = {{"nose", 7, 0.0}, {"tail", 2, 0.02}};
  const Json j = checkJson(r);
  ASSERT_EQ(j.at("anchors").size(), 2u);
  EXPECT_EQ(j.at("anchors")[1].at("name").get<std::string>(), "tail");
  EXPECT_EQ(j.at("anchors")[1].at("target_vertex").get<int>(), 2);
  EXPECT_EQ(j.at("source").at("anchors").get<int>(), 2);
  const std::vector<std::string> lines = checkLines({"a.off", "b.off", "a.pp", "b.pp"}, r);
  ASSERT_GE(lines.size(), 4u);
  EXPECT_TRUE(startsWith(lines[0], "source  a.off: ")) << lines[0];
  EXPECT_NE(lines[2].find("2 pairs matched by name; largest snap distance 1% (source), 2% (target)"), std::string::npos)
      << lines[2];
}
