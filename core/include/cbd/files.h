#pragma once
/// @file files.h
/// The file-system rules every writer and front end follows. Contract:
///  * a file is written to a temporary beside it and renamed over it (`writeTarget`), so that no
///    reader sees half a file; a device (/dev/null) is written in place;
///  * an output folder is created and probed before any computation (`OutputFolder::prepare`),
///    so that a run does not compute for minutes and then fail to save; a run that fails or is
///    cancelled removes the folders it created while they are still empty (`OutputFolder::abandon`);
///  * every failure is a Status (OutputError / FileNotFound) whose message names the path and the fix.

#include <filesystem>
#include <string>
#include <vector>

#include "cbd/status.h"

namespace cbd {

/// Why `path` cannot be read as an input file, with the fix, for FileNotFound messages: "no
/// such file (check the path)", "cannot be accessed (...permissions...)", "is a folder, not a
/// file (name a file in it)" or "is not a regular file (a device or pipe: give a file)".
std::string notAFileReason(const std::string& path);

/// Where a writer puts `path`'s contents so that no reader sees a half-written file: a temporary
/// `.NAME.tmp` beside it, then renamed over it. But a device or pipe that exists at `path`
/// (/dev/null, /dev/stdout) is returned itself, to be written in place: a rename would replace
/// the device with a file.
std::string writeTarget(const std::string& path);

/// Write `text` to `path` through `writeTarget`; OutputError naming the path on failure.
Status writeTextFile(const std::string& path, const std::string& text);

/// Whether a new file can be created in `dir` (a probe made by mkstemp and removed at once): a
/// permission check that holds for root, read-only mounts and pseudo file systems alike.
bool canCreateIn(const std::filesystem::path& dir);

/// Whether a report file can be written at `path` after a run: its folder exists and takes new
/// files and `path` is not a folder ("" and a device always can). OutputError otherwise.
Status checkWritableFile(const std::string& path, const std::string& what);

/// An output folder of one run.
class OutputFolder {
 public:
  /// Create `dir` when missing and check that it takes new files; remembers what it created.
  Status prepare(const std::string& dir);
  /// After a failure: remove the folders `prepare` created, innermost first, while empty.
  void abandon();

 private:
  std::vector<std::filesystem::path> created_;
};

/// Whether `a` and `b` name one existing file (through any path, symlink or hard link).
bool sameFile(const std::string& a, const std::string& b);

}  // namespace cbd
