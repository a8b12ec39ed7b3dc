// Anchor files: PickPoints XML, vertex lists, named points; snapping; matching by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cbd/anchors.h"
#include "support/fixtures.h"

using namespace cbd;
namespace fx = cbd::fixtures;
namespace fs = std::filesystem;

namespace {
fs::path tempDir() {
  fs::path d = fs::temp_directory_path() / ("cbd_test_anchors_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST(Anchors, ReadsMeshLabPickedPoints) {
  const std::string xml = R"(<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="10:00:00" date="2020-09-01"/>
  <User name="someone"/>
  <DataFileName name="cow.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="1" y="2" z="3" active="1" name="nose"/>
 <point x="-1.5" y="0" z="2e-3" active="0" name="unchecked"/>
 <point x="4" y="5" z="6" name="tail"/>
</PickedPoints>
)";
  const AnchorSet s = parseAnchors(xml, "mem.pp");
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_EQ(s.format, AnchorFormat::PickedPoints);
  ASSERT_EQ(s.anchors.size(), 2u);
  EXPECT_EQ(s.skippedInactive, 1);
  EXPECT_EQ(s.anchors[0].name, "nose");
  EXPECT_EQ(s.anchors[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(s.anchors[0].line, 9);
  EXPECT_EQ(s.anchors[1].name, "tail");
  EXPECT_EQ(s.anchors[1].position, Vec3(4, 5, 6));
}

TEST(Anchors, MalformedXmlReportsTheLine) {
  const std::string xml = "<!DOCTYPE PickedPoints>\n<PickedPoints>\n <point x=\"1\" y=\"2\" z=\"3\" name=\"a\"/>\n <point x=\"1\" y=\"2\n</PickedPoints>\n";
  const AnchorSet s = parseAnchors(xml, "bad.pp");
  EXPECT_EQ(s.status.code, ErrorCode::MalformedAnchors);
  EXPECT_NE(s.status.message.find("bad.pp"), std::string::npos);
  EXPECT_NE(s.status.message.find("line 4"), std::string::npos) << s.status.message;
}

TEST(Anchors, NonNumericCoordinateIsMalformed) {
  const AnchorSet s = parseAnchors("<PickedPoints>\n<point x=\"1\" y=\"abc\" z=\"3\" name=\"a\"/>\n</PickedPoints>", "p.pp");
  EXPECT_EQ(s.status.code, ErrorCode::MalformedAnchors);
  EXPECT_NE(s.status.message.find("line 2"), std::string::npos) << s.status.message;
  EXPECT_NE(s.status.message.find("'y'"), std::string::npos) << s.status.message;
}

TEST(Anchors, WrongRootIsMalformed) {
  EXPECT_EQ(parseAnchors("<Foo><point x=\"1\" y=\"2\" z=\"3\"/></Foo>", "f").status.code, ErrorCode::MalformedAnchors);
}

TEST(Anchors, DuplicateNames) {
  const AnchorSet s = parseAnchors("a 0 0 0\nb 1 0 0\na 0 1 0\n", "dup.txt");
  EXPECT_EQ(s.status.code, ErrorCode::DuplicateAnchorName);
  EXPECT_NE(s.status.message.find("lines 1 and 3"), std::string::npos) << s.status.message;
}

TEST(Anchors, VertexListLikeShrecVts) {
  const AnchorSet s = parseAnchors("12 0.5 0.25 1\n# comment\n7 1 2 3\n\n3\n", "x.vts");
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_EQ(s.format, AnchorFormat::VertexList);
  ASSERT_EQ(s.anchors.size(), 3u);
  EXPECT_EQ(s.anchors[0].vertex, 12);
  EXPECT_EQ(s.anchors[0].name, "1");
  EXPECT_EQ(s.anchors[1].name, "2");
  EXPECT_EQ(s.anchors[2].vertex, 3);
  EXPECT_FALSE(s.anchors[2].hasPosition);
  EXPECT_EQ(s.anchors[1].line, 3);
}

// What editors put around the lines: a UTF-8 byte-order mark before the first (it was read
// as part of the first index, so the file was taken for named points), and CR LF or lone CR
// line ends (a lone-CR file was one line).
TEST(Anchors, ByteOrderMarkAndLineEndsOfOtherSystems) {
  for (const std::string& text : {std::string("\xEF\xBB\xBF") + "12\n7\n3\n", std::string("12\r\n7\r\n3\r\n"),
                                  std::string("12\r7\r3"), std::string("\xEF\xBB\xBF") + "12\r7\r\n3\n"}) {
    const AnchorSet s = parseAnchors(text, "x.vts");
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    EXPECT_EQ(s.format, AnchorFormat::VertexList);
    ASSERT_EQ(s.anchors.size(), 3u);
    EXPECT_EQ(s.anchors[0].vertex, 12);
    EXPECT_EQ(s.anchors[1].vertex, 7);
    EXPECT_EQ(s.anchors[2].vertex, 3);
    EXPECT_EQ(s.anchors[2].line, 3);
  }
  // Named points: the first name is "nose", not the mark and "nose"; a bad line is numbered
  // by the lone CRs too.
  const AnchorSet named = parseAnchors("\xEF\xBB\xBFnose 1 2 3\rtail 4 5 6\r", "n.txt");
  ASSERT_TRUE(named.status.ok()) << named.status.message;
  ASSERT_EQ(named.anchors.size(), 2u);
  EXPECT_EQ(named.anchors[0].name, "nose");
  EXPECT_EQ(named.anchors[1].name, "tail");
  const AnchorSet bad = parseAnchors("nose 1 2 3\rtail 4 x 6\r", "n.txt");
  EXPECT_EQ(bad.status.code, ErrorCode::MalformedAnchors);
  EXPECT_NE(bad.status.message.find("line 2"), std::string::npos) << bad.status.message;
  // A .pp file with a mark is still XML.
  const AnchorSet pp = parseAnchors("\xEF\xBB\xBF<?xml version=\"1.0\"?>\r\n<PickedPoints>\r<point x=\"1\" y=\"2\" z=\"3\" "
                                    "name=\"a\"/>\r</PickedPoints>\r",
                                    "m.pp");
  ASSERT_TRUE(pp.status.ok()) << pp.status.message;
  ASSERT_EQ(pp.anchors.size(), 1u);
  EXPECT_EQ(pp.anchors[0].name, "a");
}

TEST(Anchors, VertexListBadLine) {
  const AnchorSet s = parseAnchors("1 0 0 0\n2 0 0\n", "x.vts");
  EXPECT_EQ(s.status.code, ErrorCode::MalformedAnchors);
  EXPECT_NE(s.status.message.find("line 2"), std::string::npos);
  EXPECT_EQ(parseAnchors("-4\n", "neg").status.code, ErrorCode::AnchorIndexOutOfRange);
}

TEST(Anchors, NamedPointsBadCoordinate) {
  const AnchorSet s = parseAnchors("nose 1 2 3\ntail 1 nan 3\n", "n.txt");
  EXPECT_EQ(s.status.code, ErrorCode::MalformedAnchors);
  EXPECT_NE(s.status.message.find("line 2"), std::string::npos);
}

TEST(Anchors, PickedPointsRoundTrip) {
  std::vector<Anchor> in;
  for (int k = 0; k < 5; ++k) {
    Anchor a;
    a.name = "p" + std::to_string(k) + (k == 3 ? " with <xml> & \"quotes\"" : "");
    a.position = Vec3(0.1 * k, -1.0 / 3.0 * k, 1e-7 * k);
    in.push_back(a);
  }
  const fs::path p = tempDir() / "round.pp";
  ASSERT_TRUE(writePickedPoints(p.string(), in, "mesh.off").ok());
  const AnchorSet out = readAnchors(p.string());
  ASSERT_TRUE(out.status.ok()) << out.status.message;
  ASSERT_EQ(out.anchors.size(), in.size());
  for (size_t k = 0; k < in.size(); ++k) {
    EXPECT_EQ(out.anchors[k].name, in[k].name);
    EXPECT_EQ(out.anchors[k].position, in[k].position);  // %.17g is exact
  }
  fs::remove_all(p.parent_path());
}

TEST(Anchors, MissingFile) {
  EXPECT_EQ(readAnchors("/nonexistent/cbd/a.pp").status.code, ErrorCode::FileNotFound);
}

TEST(Anchors, SnapToNearestVertexAndReportDistance) {
  const IndexedMesh m = fx::icosphere(2);
  const double diag = boundingBoxDiagonal(m);
  AnchorSet s;
  s.source = "s";
  Anchor a;
  a.name = "x";
  a.position = m.positions[17] * 1.001;  // slightly off the surface
  a.hasPosition = true;
  s.anchors.push_back(a);
  std::vector<SnappedAnchor> out;
  ASSERT_TRUE(snapAnchors(m, s, 0.01, "source", out).ok());
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].vertex, 17);
  EXPECT_NEAR(out[0].snapDistance, 0.001 / diag, 1e-12);
}

TEST(Anchors, OffSurface) {
  const IndexedMesh m = fx::icosphere(2);
  AnchorSet s;
  s.source = "s";
  Anchor a;
  a.name = "far";
  a.position = Vec3(3, 0, 0);
  a.hasPosition = true;
  s.anchors.push_back(a);
  std::vector<SnappedAnchor> out;
  const Status st = snapAnchors(m, s, 0.01, "source", out);
  EXPECT_EQ(st.code, ErrorCode::AnchorOffSurface);
  EXPECT_NE(st.message.find("'far'"), std::string::npos);
}

TEST(Anchors, IndexLineWithOtherCoordinatesNamesTheVertexAndTheLine) {
  // "index x y z" whose coordinates are another point's: the listed vertex stays the anchor, and
  // the error says it is away from the coordinates (not that some nearest vertex is).
  const IndexedMesh m = fx::icosphere(2);
  const Vec3& p = m.positions[5];
  const AnchorSet s = parseAnchors("0\n1\n7 " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
                                       std::to_string(p.z()) + "\n",
                                   "idx.vts");
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  std::vector<SnappedAnchor> out;
  const Status st = snapAnchors(m, s, 0.01, "source", out);
  EXPECT_EQ(st.code, ErrorCode::AnchorOffSurface);
  EXPECT_NE(st.message.find("line 3: vertex 7 of the source mesh lies away from the coordinates"), std::string::npos)
      << st.message;
}

TEST(Anchors, TwoAnchorsOnOneVertex) {
  const IndexedMesh m = fx::icosphere(2);
  AnchorSet s = parseAnchors("a 1 0 0\nb 0.999 0.001 0\n", "s");
  ASSERT_TRUE(s.status.ok());
  std::vector<SnappedAnchor> out;
  EXPECT_EQ(snapAnchors(m, s, 0.05, "source", out).code, ErrorCode::AnchorsShareVertex);
}

TEST(Anchors, IndexOutOfRange) {
  const IndexedMesh m = fx::tetrahedron();
  AnchorSet s = parseAnchors("0\n1\n4\n", "t.vts");
  std::vector<SnappedAnchor> out;
  const Status st = snapAnchors(m, s, 0.01, "target", out);
  EXPECT_EQ(st.code, ErrorCode::AnchorIndexOutOfRange);
  EXPECT_NE(st.message.find("line 3"), std::string::npos);
}

TEST(Anchors, MatchByName) {
  AnchorSet a = parseAnchors("x 0 0 0\ny 1 0 0\nz 2 0 0\n", "a");
  AnchorSet b = parseAnchors("z 0 0 0\nx 1 0 0\ny 2 0 0\n", "b");
  std::vector<int> ia, ib;
  ASSERT_TRUE(matchAnchors(a, b, ia, ib).ok());
  EXPECT_EQ(ia, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(ib, (std::vector<int>{1, 2, 0}));
}

TEST(Anchors, NameOnOneSideOnly) {
  AnchorSet a = parseAnchors("x 0 0 0\ny 1 0 0\nz 2 0 0\n", "a.txt");
  AnchorSet b = parseAnchors("x 0 0 0\ny 1 0 0\nw 2 0 0\n", "b.txt");
  std::vector<int> ia, ib;
  const Status s = matchAnchors(a, b, ia, ib);
  EXPECT_EQ(s.code, ErrorCode::AnchorNameMismatch);
  EXPECT_NE(s.message.find("'z'"), std::string::npos) << s.message;
  EXPECT_TRUE(ia.empty());
}

TEST(Anchors, AllPointsInactiveIsNamedAsSuch) {
  // Every point unchecked in PickPoints: "no anchors" is the problem, not mismatching names.
  const AnchorSet off = parseAnchors(
      "<PickedPoints>\n<point x=\"1\" y=\"2\" z=\"3\" active=\"0\" name=\"a\"/>\n"
      "<point x=\"4\" y=\"5\" z=\"6\" active=\"0\" name=\"b\"/>\n</PickedPoints>",
      "off.pp");
  ASSERT_TRUE(off.status.ok()) << off.status.message;
  EXPECT_TRUE(off.anchors.empty());
  EXPECT_EQ(off.skippedInactive, 2);
  const AnchorSet on = parseAnchors("a 1 2 3\nb 4 5 6\n", "on.txt");
  ASSERT_TRUE(on.status.ok()) << on.status.message;
  std::vector<int> si, ti;
  const Status s = matchAnchors(on, off, si, ti);
  EXPECT_EQ(s.code, ErrorCode::TooFewAnchors);
  EXPECT_NE(s.message.find("off.pp"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("inactive"), std::string::npos) << s.message;
  EXPECT_TRUE(si.empty() && ti.empty());
  // No point at all (an empty file): too few anchors too, saying the file has none.
  const AnchorSet none = parseAnchors("# only a comment\n", "none.txt");
  ASSERT_TRUE(none.status.ok()) << none.status.message;
  const Status e = matchAnchors(none, on, si, ti);
  EXPECT_EQ(e.code, ErrorCode::TooFewAnchors);
  EXPECT_NE(e.message.find("none.txt: no anchors"), std::string::npos) << e.message;
  // Some inactive: the mismatch names the missing anchor and says inactive points were left out.
  const AnchorSet some = parseAnchors(
      "<PickedPoints>\n<point x=\"1\" y=\"2\" z=\"3\" name=\"a\"/>\n"
      "<point x=\"4\" y=\"5\" z=\"6\" active=\"0\" name=\"b\"/>\n</PickedPoints>",
      "some.pp");
  const Status m = matchAnchors(on, some, si, ti);
  EXPECT_EQ(m.code, ErrorCode::AnchorNameMismatch);
  EXPECT_NE(m.message.find("'b'"), std::string::npos) << m.message;
  EXPECT_NE(m.message.find("1 of the target's"), std::string::npos) << m.message;
}
