// Typed errors (status.h): every code has a stable name, a description and a distinct, stable exit
// code (the file-system helpers are tested in test_files.cpp).
#include <gtest/gtest.h>

#include <cctype>
#include <map>
#include <set>
#include <string>

#include "cbd/status.h"

using namespace cbd;

TEST(Status, EveryCodeIsListedOnceInEnumOrder) {
  int count = 0;
  const ErrorCode* codes = allErrorCodes(count);
  ASSERT_NE(codes, nullptr);
  // The last enumerator is Cancelled: every value from Ok up to it is listed, in order.
  ASSERT_EQ(count, static_cast<int>(ErrorCode::Cancelled) + 1);
  for (int i = 0; i < count; ++i) EXPECT_EQ(static_cast<int>(codes[i]), i) << "position " << i;
}

TEST(Status, NamesAreUniqueSnakeCaseAndEveryCodeIsDescribed) {
  int count = 0;
  const ErrorCode* codes = allErrorCodes(count);
  std::set<std::string> names, descriptions;
  for (int i = 0; i < count; ++i) {
    const std::string name = errorCodeName(codes[i]), description = errorCodeDescription(codes[i]);
    EXPECT_FALSE(name.empty()) << "code " << i;
    for (char c : name) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || c == '_') << "'" << name << "'";
    EXPECT_TRUE(names.insert(name).second) << "name '" << name << "' used twice";
    EXPECT_FALSE(description.empty()) << name;
    EXPECT_TRUE(descriptions.insert(description).second) << "description of " << name << " used twice";
  }
  EXPECT_STREQ(errorCodeName(ErrorCode::Ok), "ok");
  EXPECT_STREQ(errorCodeName(ErrorCode::OpenBoundary), "open_boundary");
}

TEST(Status, ExitCodesAreStableAndDistinct) {
  // Scripts test these numbers (README's table, `cbd exit-codes`): a code may be appended, never
  // moved. The table pins every code's name and exit code.
  const std::map<std::string, int> pinned = {
      {"ok", 0},                         {"invalid_argument", 2},          {"file_not_found", 12},
      {"unsupported_format", 13},        {"malformed_mesh", 14},           {"output_error", 15},
      {"empty_mesh", 16},                {"not_triangles", 17},            {"invalid_coordinates", 18},
      {"degenerate_face", 19},           {"duplicate_face", 20},           {"open_boundary", 21},
      {"non_manifold_edge", 22},         {"non_manifold_vertex", 23},      {"inconsistent_orientation", 24},
      {"multiple_components", 25},       {"genus_mismatch", 26},           {"malformed_anchors", 27},
      {"anchor_name_mismatch", 28},      {"duplicate_anchor_name", 29},    {"anchor_index_out_of_range", 30},
      {"anchor_off_surface", 31},        {"anchors_share_vertex", 32},     {"too_few_anchors", 33},
      {"too_many_anchors", 34},          {"layout_failed", 35},            {"internal_error", 36},
      {"orientation_mismatch", 37},      {"cancelled", 38}};
  int count = 0;
  const ErrorCode* codes = allErrorCodes(count);
  ASSERT_EQ(count, static_cast<int>(pinned.size()));
  std::set<int> exits;
  for (int i = 0; i < count; ++i) {
    const std::string name = errorCodeName(codes[i]);
    const int exit = exitCode(codes[i]);
    const auto it = pinned.find(name);
    ASSERT_NE(it, pinned.end()) << "unknown name " << name;
    EXPECT_EQ(exit, it->second) << name;
    EXPECT_TRUE(exits.insert(exit).second) << name << " shares exit code " << exit;
    // 1 is what a crash or an uncaught exception looks like to a shell; 126+ are the shell's own.
    if (codes[i] != ErrorCode::Ok) {
      EXPECT_GE(exit, 2) << name;
      EXPECT_LT(exit, 126) << name;
    }
  }
}

TEST(Status, OkOnlyForOk) {
  const Status ok = Status::success();
  EXPECT_TRUE(ok.ok());
  EXPECT_TRUE(static_cast<bool>(ok));
  EXPECT_EQ(ok.code, ErrorCode::Ok);
  const Status bad = Status::error(ErrorCode::OpenBoundary, "edge 3-4");
  EXPECT_FALSE(bad.ok());
  EXPECT_FALSE(static_cast<bool>(bad));
  EXPECT_EQ(bad.code, ErrorCode::OpenBoundary);
  EXPECT_EQ(bad.message, "edge 3-4");
}

TEST(Status, CountedUsesTheSingularForOneOnly) {
  EXPECT_EQ(counted(1, "vertex", "vertices"), "1 vertex");
  EXPECT_EQ(counted(0, "vertex", "vertices"), "0 vertices");
  EXPECT_EQ(counted(3, "face", "faces"), "3 faces");
  EXPECT_EQ(counted(-1, "face", "faces"), "-1 faces");
  EXPECT_EQ(counted(10000000000LL, "face", "faces"), "10000000000 faces");
}
