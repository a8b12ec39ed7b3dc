#include "cbd/files.h"

#include <fstream>
#include <system_error>

#include <unistd.h>

namespace cbd {

namespace fs = std::filesystem;

std::string writeTarget(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!ec && fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st)) return path;
  const fs::path target(path);
  return (target.parent_path() / ("." + target.filename().string() + ".tmp")).string();
}

std::string notAFileReason(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) return "no such file (check the path)";
  if (ec || st.type() == fs::file_type::none)
    return "cannot be accessed (check the permissions of the folders on its path)";
  if (fs::is_directory(st)) return "is a folder, not a file (name a file in it)";
  return "is not a regular file (a device or pipe: give a file)";
}

Status writeTextFile(const std::string& path, const std::string& text) {
  const fs::path target(path);
  const fs::path tmp = writeTarget(path);
  const Status failed = Status::error(
      ErrorCode::OutputError,
      "cannot write '" + path + "' (check that its folder exists and is writable, and that it does not name a folder)");
  {
    std::ofstream out(tmp);
    if (!out) return failed;
    out << text;
    if (!out.good()) return failed;
  }
  if (tmp == target) return Status::success();  // a device, written in place
  std::error_code ec, ignored;
  fs::rename(tmp, target, ec);  // fails onto a folder, which is reported as such
  if (ec) {
    fs::remove(tmp, ignored);
    return failed;
  }
  return Status::success();
}

bool canCreateIn(const fs::path& dir) {
  std::string probe = (dir / ".cbd-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

Status checkWritableFile(const std::string& path, const std::string& what) {
  if (path.empty() || path == "-") return Status::success();
  if (writeTarget(path) == path) return Status::success();  // a device: written in place
  std::error_code ec;
  const fs::path file(path);
  const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (fs::is_directory(file, ec) || !fs::is_directory(folder, ec) || !canCreateIn(folder))
    return Status::error(ErrorCode::OutputError,
                         "cannot write " + what + " '" + path +
                             "' (check that its folder exists and is writable, and that it does not name a folder)");
  return Status::success();
}

Status OutputFolder::prepare(const std::string& dir) {
  std::error_code ec;
  if (dir.empty())
    return Status::error(ErrorCode::InvalidArgument, "no output folder given: name one");
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return Status::error(ErrorCode::OutputError, "output folder '" + dir + "' is a file: choose another output folder");
  // The folders that do not exist yet, innermost first ("a/b/.." creates a and a/b).
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(dir, ec); !p.empty() && p != p.parent_path() && !fs::exists(p, ec); p = p.parent_path()) {
    const std::string name = p.filename().string();
    if (!name.empty() && name != "." && name != "..") missing.push_back(p);
  }
  std::error_code created;
  fs::create_directories(dir, created);
  if (!fs::is_directory(dir, ec))
    return Status::error(ErrorCode::OutputError, "cannot create output folder '" + dir + "'" +
                                                     (created ? " (" + created.message() + ")" : "") +
                                                     ": choose one under a writable folder");
  created_ = missing;
  if (!canCreateIn(dir))
    return Status::error(ErrorCode::OutputError, "cannot write into output folder '" + dir +
                                                     "': check its permissions, or choose another output folder");
  return Status::success();
}

void OutputFolder::abandon() {
  for (const fs::path& dir : created_) {
    std::error_code ec;
    if (!fs::is_empty(dir, ec) || ec || !fs::remove(dir, ec)) break;
  }
  created_.clear();
}

bool sameFile(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty() || a == "-" || b == "-") return false;
  std::error_code ec;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

}  // namespace cbd
