// File-system rules (files.h): whole files or none, output folders prepared before a run and
// removed again after a failure while empty, clashes between paths seen through links.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "cbd/files.h"

using namespace cbd;
namespace fs = std::filesystem;

namespace {
fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / ("cbd_files_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(Files, TextGoesThroughATemporaryBesideTheFile) {
  const fs::path d = freshDir("text");
  const fs::path f = d / "report.json";
  EXPECT_EQ(fs::path(writeTarget(f.string())), d / ".report.json.tmp");
  ASSERT_TRUE(writeTextFile(f.string(), "one\n"));
  ASSERT_TRUE(writeTextFile(f.string(), "two\n"));  // replaces it whole
  EXPECT_EQ(slurp(f), "two\n");
  EXPECT_FALSE(fs::exists(d / ".report.json.tmp"));
}

TEST(Files, ADeviceIsWrittenInPlace) {
  EXPECT_EQ(writeTarget("/dev/null"), "/dev/null");
  EXPECT_TRUE(writeTextFile("/dev/null", "x"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(Files, AFolderIsNoFileToWrite) {
  const fs::path d = freshDir("folder");
  fs::create_directories(d / "sub");
  const Status s = writeTextFile((d / "sub").string(), "x");
  EXPECT_EQ(s.code, ErrorCode::OutputError);
  EXPECT_NE(s.message.find("sub"), std::string::npos) << s.message;
  EXPECT_TRUE(fs::is_directory(d / "sub"));
  EXPECT_FALSE(fs::exists(d / ".sub.tmp"));
  EXPECT_EQ(checkWritableFile((d / "sub").string(), "JSON report").code, ErrorCode::OutputError);
  EXPECT_EQ(checkWritableFile((d / "missing" / "r.json").string(), "JSON report").code, ErrorCode::OutputError);
  EXPECT_TRUE(checkWritableFile((d / "r.json").string(), "JSON report"));
  EXPECT_TRUE(checkWritableFile("-", "JSON report"));
  EXPECT_TRUE(checkWritableFile("", "JSON report"));
}

TEST(Files, AFailedRunRemovesTheFoldersItCreatedWhileEmpty) {
  const fs::path d = freshDir("abandon");
  {
    OutputFolder out;
    ASSERT_TRUE(out.prepare((d / "a" / "b" / "c").string()));
    EXPECT_TRUE(fs::is_directory(d / "a" / "b" / "c"));
    out.abandon();
    EXPECT_FALSE(fs::exists(d / "a")) << "all three created folders go";
    EXPECT_TRUE(fs::is_directory(d)) << "the folder that was there stays";
  }
  {
    fs::create_directories(d / "kept");
    OutputFolder out;
    ASSERT_TRUE(out.prepare((d / "kept" / "new").string()));
    std::ofstream(d / "kept" / "new" / "file") << "x";
    out.abandon();
    EXPECT_TRUE(fs::exists(d / "kept" / "new" / "file")) << "a folder with a file in it stays";
  }
}

TEST(Files, AnOutputFolderThatIsAFileIsRefused) {
  const fs::path d = freshDir("isfile");
  std::ofstream(d / "plain") << "x";
  OutputFolder out;
  const Status s = out.prepare((d / "plain").string());
  EXPECT_EQ(s.code, ErrorCode::OutputError);
  EXPECT_NE(s.message.find("is a file"), std::string::npos) << s.message;
  EXPECT_EQ(out.prepare((d / "plain" / "below").string()).code, ErrorCode::OutputError);
  EXPECT_EQ(out.prepare("").code, ErrorCode::InvalidArgument);
}

TEST(Files, SameFileSeesThroughLinksButNotThroughNames) {
  const fs::path d = freshDir("same");
  std::ofstream(d / "mesh.off") << "OFF\n";
  fs::create_symlink(d / "mesh.off", d / "link.off");
  fs::create_hard_link(d / "mesh.off", d / "hard.off");
  std::ofstream(d / "other.off") << "OFF\n";
  EXPECT_TRUE(sameFile((d / "mesh.off").string(), (d / "link.off").string()));
  EXPECT_TRUE(sameFile((d / "mesh.off").string(), (d / "hard.off").string()));
  EXPECT_TRUE(sameFile((d / "mesh.off").string(), (d / "." / "mesh.off").string()));
  EXPECT_FALSE(sameFile((d / "mesh.off").string(), (d / "other.off").string()));
  EXPECT_FALSE(sameFile((d / "mesh.off").string(), (d / "missing.off").string()));
  EXPECT_FALSE(sameFile((d / "mesh.off").string(), "-"));
}

TEST(Files, NotAFileReasonTellsMissingFolderAndDeviceApart) {
  const fs::path dirPath = freshDir("reason2");
  const std::string missing = (dirPath / "missing.off").string();
  EXPECT_EQ(notAFileReason(missing), "no such file (check the path)");
  EXPECT_EQ(notAFileReason(dirPath.string()), "is a folder, not a file (name a file in it)");
  EXPECT_EQ(notAFileReason("/dev/null"), "is not a regular file (a device or pipe: give a file)");
}

TEST(Files, NotAFileReasonNamesAFolderThatCannotBeSearched) {
  if (geteuid() == 0) GTEST_SKIP() << "root reads every folder: no permission error to provoke";
  const fs::path dirPath = freshDir("locked");
  const fs::path locked = dirPath / "locked";
  fs::create_directories(locked);
  std::ofstream(locked / "mesh.off") << "OFF\n";
  fs::permissions(locked, fs::perms::none);
  const std::string reason = notAFileReason((locked / "mesh.off").string());
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_EQ(reason, "cannot be accessed (check the permissions of the folders on its path)");
}

TEST(Files, WriteTargetIsAHiddenTemporaryBesideTheFileButADeviceItself) {
  const fs::path dirPath = freshDir("target");
  const fs::path file = dirPath / "mst.ply";
  const std::string expected = (dirPath / ".mst.ply.tmp").string();
  EXPECT_EQ(writeTarget(file.string()), expected);  // not there yet
  std::ofstream(file) << "x";
  EXPECT_EQ(writeTarget(file.string()), expected);  // a regular file is replaced by a rename
  EXPECT_EQ(writeTarget("/dev/null"), "/dev/null");  // a device is written in place
  EXPECT_EQ(writeTarget("out.json"), ".out.json.tmp");  // a bare name stays in the working folder
}
