// cbd: command-line front end. Parse the arguments, call one job (cbd/jobs.h), print its report
// (cbd/report.h). Every failure is one line on stderr and a distinct exit code (cbd exit-codes).

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cbd/files.h"
#include "cbd/jobs.h"
#include "cbd/report.h"

namespace {

using cbd::Json;

/// With `--json -`: the real standard output, kept for the report alone, while the human-readable
/// log goes to standard error (so that stdout parses as JSON).
int jsonStdout = -1;

bool writeJson(const std::string& path, const Json& j) {
  if (path.empty()) return true;
  const std::string text = j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  if (path != "-") return cbd::writeTextFile(path, text).ok();
  if (jsonStdout < 0) {
    std::cout << text;
    return static_cast<bool>(std::cout.flush());
  }
  std::fflush(stdout);
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(jsonStdout, text.data() + done, text.size() - done);
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

/// A command line that does not parse still gets its JSON report when it names one (`--json
/// PATH`, `--json=PATH`, `-` for stdout), so that a script reading reports sees the error.
/// Since the options are not known, only onto a new file, a device or an earlier report (a JSON
/// object with a "status"): never onto an input or another output. Nor for a command without
/// a --json option (sample-anchors), where "--json" is itself the error.
void writeParseErrorReport(CLI::App& app, int argc, char** argv, const std::string& message) {
  namespace fs = std::filesystem;
  if (argc >= 2)
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
      if (sub->get_name() == argv[1] && !sub->get_option_no_throw("--json")) return;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string path;
    if (arg == "--json" && i + 1 < argc) path = argv[i + 1];
    else if (arg.rfind("--json=", 0) == 0) path = arg.substr(7);
    if (path.empty() || (path[0] == '-' && path != "-")) continue;
    std::error_code ec;
    if (path != "-" && fs::exists(path, ec) && cbd::writeTarget(path) != path) {
      std::ifstream existing(path);
      const Json earlier = Json::parse(existing, nullptr, /*allow_exceptions=*/false);
      if (!fs::is_regular_file(path, ec) || !earlier.is_object() || !earlier.contains("status")) return;
    }
    Json j;
    j["status"] = cbd::errorCodeName(cbd::ErrorCode::InvalidArgument);
    j["message"] = message;
    writeJson(path, j);
    return;
  }
}

/// The report's status, the error line, the exit code.
int finish(const cbd::Status& status, Json j, const std::string& jsonPath) {
  j["status"] = cbd::errorCodeName(status.code);
  j["message"] = status.message;
  const bool reported = writeJson(jsonPath, j);
  // The run's own error first, also when the report cannot tell it.
  if (!status.ok()) std::cerr << "cbd: error: " << cbd::errorCodeName(status.code) << ": " << status.message << "\n";
  if (!reported) {
    std::cerr << "cbd: error: output_error: cannot write JSON report '" << jsonPath
              << "' (check that its folder exists and is writable, and that it does not name a folder)\n";
    return cbd::exitCode(cbd::ErrorCode::OutputError);
  }
  return cbd::exitCode(status.code);
}

void print(const std::vector<std::string>& lines) {
  for (const std::string& l : lines) std::printf("%s\n", l.c_str());
}

void warn(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());
}

// --- progress on the terminal, and Ctrl-C

volatile std::sig_atomic_t interrupted = 0;

extern "C" void onInterrupt(int signal) {
  interrupted = 1;
  std::signal(signal, SIG_DFL);  // a second Ctrl-C ends the process at once
}

/// A one-line bar on stderr when it is a terminal (silent otherwise, so that logs and `--json -`
/// stay clean); Ctrl-C or SIGTERM cancels the job, which then writes nothing.
class TerminalProgress {
 public:
  TerminalProgress() : tty_(::isatty(STDERR_FILENO) == 1) {
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
  }
  ~TerminalProgress() { clear(); }
  cbd::Progress progress() {
    return cbd::Progress([this](int percent, const char* stage) {
      if (tty_) {
        const int width = 30, done = percent * width / 100;
        std::fprintf(stderr, "\r\033[K[%s%s] %3d%% %s", std::string(static_cast<size_t>(done), '#').c_str(),
                     std::string(static_cast<size_t>(width - done), '.').c_str(), percent, stage);
        std::fflush(stderr);
        shown_ = true;
      }
      return interrupted == 0;
    });
  }
  void clear() {
    if (!shown_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    shown_ = false;
  }

 private:
  bool tty_;
  bool shown_ = false;
};

/// A number in [lo, hi]; NaN, which CLI::Range lets through (every comparison with it is
/// false), is refused with the option's name.
CLI::Validator finiteRange(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double v = 0;
        try {
          size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) throw std::invalid_argument(text);
        } catch (const std::out_of_range&) {
          return "'" + text + "' is beyond the range of a double";
        } catch (const std::exception&) {
          return "'" + text + "' is not a number";
        }
        if (!(v >= lo && v <= hi))
          return "'" + text + "' is not a number in [" + CLI::detail::to_string(lo) + ", " + CLI::detail::to_string(hi) + "]";
        return std::string();
      },
      "FLOAT in [" + CLI::detail::to_string(lo) + " - " + CLI::detail::to_string(hi) + "]");
}

CLI::Range range(cbd::IntRange r) { return CLI::Range(r.lo, r.hi); }

// --- commands

struct CheckArgs {
  cbd::InputFiles files;
  double snapTolerance = 0.01;
  std::string jsonPath;
};

int runCheck(const CheckArgs& a) {
  cbd::ValidationOptions opt;
  opt.snapTolerance = a.snapTolerance;
  cbd::LoadedInput in;
  cbd::loadAndValidate(a.files, opt, in);
  if (in.report.status) print(cbd::checkLines(a.files, in.report));
  return finish(in.report.status, cbd::checkJson(in.report), a.jsonPath);
}

/// Options shared by `layout` and `map`.
struct RunArgs {
  std::string mesh, anchors, out, jsonPath;
  std::string target, targetAnchors;
  std::string method = "voronoi";
  int minEdgeNodes = 3;
  bool singleEdgeNode = false;
  double snapTolerance = 0.01;
  int morph = 0;
  int smooth = 0;
  int straighten = cbd::PathStraighteningOptions{}.rounds;
  bool noUntangle = false;
  std::string mapStage = "untangle";
  bool flipPaths = false;

  cbd::InputFiles files() const { return {mesh, target, anchors, targetAnchors}; }
  cbd::ValidationOptions validation() const {
    cbd::ValidationOptions v;
    v.snapTolerance = snapTolerance;
    return v;
  }
  cbd::CrossParameterizationOptions pipeline() const {
    cbd::CrossParameterizationOptions o;
    o.method = method == "greedy" ? cbd::LayoutMethod::Greedy : cbd::LayoutMethod::Voronoi;
    o.edgeNodes.minEdgeNodes = singleEdgeNode ? 1 : minEdgeNodes;
    o.edgeNodes.adaptive = !singleEdgeNode;
    o.smoothing.iterations = smooth;
    o.straightening.rounds = straighten;
    o.untangle = !noUntangle;
    o.mapStage = mapStage == "optimize" ? cbd::MapStage::Optimize : cbd::MapStage::Untangle;
    o.flipPaths = flipPaths;
    return o;
  }
  cbd::LayoutJob layoutJob() const { return {files(), validation(), pipeline(), out, jsonPath}; }
  cbd::MapJob mapJob() const { return {files(), validation(), pipeline(), out, morph, jsonPath}; }
};

/// When the report file cannot be written, the report of that error goes nowhere.
std::string reportPathFor(const cbd::Status& s, const std::string& jsonPath) {
  return s.code == cbd::ErrorCode::OutputError && s.message.rfind("cannot write JSON report", 0) == 0 ? "" : jsonPath;
}

int runLayout(const RunArgs& a) {
  const cbd::LayoutJob job = a.layoutJob();
  cbd::LayoutJobResult r;
  {
    TerminalProgress bar;
    cbd::runLayoutJob(job, r, bar.progress());
  }
  warn(job.paired() ? cbd::inputWarnings(r.input.report) : r.single.report.warnings);
  if (r.status) {
    warn(cbd::layoutWarnings(r.layouts));
    print(cbd::layoutJobLines(job, r));
  }
  return finish(r.status, cbd::layoutJobJson(job, r), reportPathFor(r.status, a.jsonPath));
}

int runMap(const RunArgs& a) {
  const cbd::MapJob job = a.mapJob();
  cbd::MapJobResult r;
  {
    TerminalProgress bar;
    cbd::runMapJob(job, r, bar.progress());
  }
  warn(cbd::inputWarnings(r.input.report));
  if (r.status) {
    warn(cbd::layoutWarnings(r.result.layouts));
    print(cbd::mapJobLines(job, r));
  }
  return finish(r.status, cbd::mapJobJson(job, r), reportPathFor(r.status, a.jsonPath));
}

struct SampleArgs {
  std::string mesh, out;
  int count = 0;
  int seed = 0;
};

int runSample(const SampleArgs& a) {
  cbd::SampleJobResult r;
  cbd::runSampleJob({a.mesh, a.count, a.seed, a.out}, r);
  warn(r.warnings);
  if (r.status)
    std::printf("wrote %s to %s\n", cbd::counted(static_cast<long long>(r.anchors.size()), "anchor", "anchors").c_str(),
                a.out.c_str());
  return finish(r.status, Json{}, "");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "cbd: common base domains by cues from the Voronoi diagram of anchor points, and the\n"
      "cross-parameterization between two closed triangle meshes built on them\n"
      "(Kwok, Zhang & Wang, Graphical Models 2012)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cbd 0.1.0");

  CheckArgs check;
  CLI::App* cmdCheck = app.add_subcommand(
      "check",
      "Validate a source/target mesh pair and their anchors; print vertices, faces, genus, anchors "
      "and snap distances. Exit 0 when the pair can be processed, else a distinct code per problem.");
  cmdCheck->add_option("--source,-s", check.files.sourceMesh, "source mesh (.ply, .off, .obj, .stl)")->required();
  cmdCheck->add_option("--target,-t", check.files.targetMesh, "target mesh (.ply, .off, .obj, .stl)")->required();
  cmdCheck->add_option("--source-anchors", check.files.sourceAnchors,
                       "source anchors: MeshLab PickPoints .pp, 'index [x y z]' lines, or 'name x y z' lines")
      ->required();
  cmdCheck->add_option("--target-anchors", check.files.targetAnchors, "target anchors, same formats; matched by name")
      ->required();
  cmdCheck->add_option("--snap-tolerance", check.snapTolerance,
                       "largest allowed anchor-to-vertex distance, as a fraction of the bounding-box diagonal")
      ->capture_default_str()
      ->check(finiteRange(0.0, cbd::kMaxSnapTolerance));
  cmdCheck->add_option("--json", check.jsonPath,
                       "also write a JSON report to this file ('-': to stdout, the log then goes to stderr)");

  auto addRunOptions = [](CLI::App* cmd, RunArgs& r, bool targetRequired) {
    cmd->add_option("--source,-s", r.mesh, "source mesh (.ply, .off, .obj, .stl)")->required();
    cmd->add_option("--source-anchors", r.anchors, "source anchors (.pp, vertex list or name x y z)")->required();
    auto* t = cmd->add_option("--target,-t", r.target, "target mesh (.ply, .off, .obj, .stl)");
    auto* ta = cmd->add_option("--target-anchors", r.targetAnchors, "target anchors, matched to the source's by name");
    if (targetRequired) {
      t->required();
      ta->required();
    } else {
      ta->needs(t);
      t->needs(ta);
    }
    cmd->add_option("--out,-o", r.out, "output folder (created when missing)")->required();
    cmd->add_option("--method", r.method,
                    "voronoi: the Voronoi-cue method (Kwok et al. 2012); greedy: the greedy shortest-path baseline "
                    "(Kraevoy & Sheffer 2004), which needs a target")
        ->capture_default_str()
        ->check(CLI::IsMember({"voronoi", "greedy"}));
    auto* b = cmd->add_option("--min-edge-nodes", r.minEdgeNodes, "b: minimum edge nodes per edge (adaptive: max(b, b*l/lbar))")
        ->capture_default_str()
        ->check(range(cbd::kMinEdgeNodesRange));
    cmd->add_flag("--single-edge-node", r.singleEdgeNode, "one edge node per edge, no adaptivity (the paper's E1 setting)")
        ->excludes(b);
    cmd->add_option("--snap-tolerance", r.snapTolerance, "largest anchor snap distance (fraction of bbox diagonal)")
        ->capture_default_str()
        ->check(finiteRange(0.0, cbd::kMaxSnapTolerance));
    cmd->add_flag("--flip-paths", r.flipPaths,
                  "Voronoi method with a target: after both layouts are built, replace each path by the other diagonal of its two "
                  "patches when that is shorter on both surfaces together and both layouts stay consistent (the "
                  "greedy baseline's path flipping, which that method always does)")
        ->needs(t);
    cmd->add_option("--json", r.jsonPath, "also write a JSON report to this file ('-': to stdout, the log then goes to stderr)");
  };
  RunArgs layout;
  CLI::App* cmdLayout = app.add_subcommand(
      "layout",
      "Build the base domain on the source (Sec. 5.1): Voronoi clusters of the anchors, a path across every cut, "
      "triangulation of the rest; with --target, the same layout on the target too (Sec. 5.2), in OUT/source and "
      "OUT/target, corresponding patches in the same colour. Writes layout.ply (faces coloured by patch) and paths.ply "
      "per surface, and with the Voronoi method clusters.ply (faces coloured by Voronoi cluster).");
  addRunOptions(cmdLayout, layout, false);

  RunArgs map;
  CLI::App* cmdMap = app.add_subcommand(
      "map",
      "Cross-parameterize source and target: common base domains, patch parameterizations, the composed map. "
      "Writes OUT/mst.ply (the source's vertices in input order at their images on the target, the source's faces; "
      "face quality = L2 stretch), OUT/mts.ply (the inverse), OUT/correspondence.txt, both layouts, and metrics.");
  addRunOptions(cmdMap, map, true);
  cmdMap->add_option("--smooth", map.smooth,
                     "N sweeps relaxing M_st across patch boundaries; moves that would flip a triangle are rejected "
                     "(mts.ply, the inverse map, is not smoothed)")
      ->capture_default_str()
      ->check(range(cbd::kSmoothingIterationsRange));
  cmdMap->add_option("--straighten", map.straighten,
                     "N rounds straightening every path of both layouts inside its two patches (the diagonal of "
                     "their quadrilateral mapped onto a square; the same for either method), before the patches "
                     "are parameterized; 0: the paths as traced; at most 8: every round splits mesh edges along "
                     "the paths, the time grows steeply with the rounds, and the paths settle within a few)")
      ->capture_default_str()
      ->check(range(cbd::kStraightenRoundsRange));
  cmdMap->add_option("--map-stage", map.mapStage,
                     "untangle: remove flipped triangles of M_st and M_ts, then polish (the default); optimize "
                     "(experimental): M_st optimized in the base domain by Newton's method, injective there, "
                     "M_ts its exact inverse, but with flipped triangles left (see docs/algorithm.md)")
      ->capture_default_str()
      ->check(CLI::IsMember({"untangle", "optimize"}));
  cmdMap->add_flag("--no-untangle", map.noUntangle,
                   "keep the composed map as it is: do not move the images of the vertices of flipped M_st / M_ts "
                   "triangles over the target (the default removes most flips, then polishes the map; see docs/algorithm.md)");
  cmdMap->add_option("--morph", map.morph, "also write K meshes OUT/morph_000.ply ... blending the source (fitted onto the target by its anchors) into M_st; "
                     "later frames of an earlier, longer sequence in OUT are removed")
      ->check(range(cbd::kMorphFramesRange));

  SampleArgs sample;
  CLI::App* cmdSample = app.add_subcommand(
      "sample-anchors",
      "Write N anchors spread by geodesic farthest-point sampling to a MeshLab .pp file. The mesh must pass "
      "the checks of `cbd check` (closed, manifold, finite coordinates...).");
  cmdSample->add_option("--mesh,-m", sample.mesh, "mesh (.ply, .off, .obj, .stl)")->required();
  cmdSample->add_option("--count,-n", sample.count, "number of anchors")->required()->check(CLI::Range(1, 100000));
  cmdSample->add_option("--seed", sample.seed, "index of the first vertex (one some face uses)")->capture_default_str();
  cmdSample->add_option("--out,-o", sample.out, "output .pp file")->required();

  CLI::App* cmdCodes = app.add_subcommand(
      "exit-codes", "List every exit code with its status name (as in the JSON \"status\") and meaning.");

  // A first word that is neither an option nor a command (CLI11 would say only that a
  // subcommand is required).
  if (argc >= 2 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      const std::string message = "unknown command '" + std::string(argv[1]) + "': one of " + names + " (see cbd --help)";
      std::cerr << "cbd: error: invalid_argument: " << message << "\n";
      writeParseErrorReport(app, argc, argv, message);
      return cbd::exitCode(cbd::ErrorCode::InvalidArgument);
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // CLI11 checks required options, and options that need one another, before unknown ones: a
    // misspelt option would be reported as the option it was meant to be, or as an "argument
    // not expected". Whatever the error, an unknown option is named first, by its command.
    std::string message = std::string(e.what()) + " (see cbd --help)";
    // Only words before a "--" can be options, and the app's own only before the command.
    const int end = static_cast<int>(std::find(argv + 1, argv + argc, std::string("--")) - argv);
    int command = end;
    for (const CLI::App* sub : app.get_subcommands())
      command = std::min(command, static_cast<int>(std::find(argv + 1, argv + end, sub->get_name()) - argv));
    std::vector<std::pair<const CLI::App*, std::string>> extras;
    for (const std::string& extra : app.remaining())
      if (std::find(argv + 1, argv + command, extra) != argv + command) extras.emplace_back(nullptr, extra);
    for (const CLI::App* sub : app.get_subcommands())
      for (const std::string& extra : sub->remaining())
        if (std::find(argv + 1, argv + end, extra) != argv + end) extras.emplace_back(sub, extra);
    for (const auto& [sub, extra] : extras)
      if (extra.size() > 1 && extra[0] == '-' && !std::isdigit(static_cast<unsigned char>(extra[1])) && extra[1] != '.') {
        const std::string option = extra.substr(0, extra.find('='));
        message = sub ? "unknown option '" + option + "' of '" + sub->get_name() + "' (see cbd " + sub->get_name() + " --help)"
                      : "unknown option '" + option + "' (options go after the command; see cbd --help)";
        break;
      }
    std::cerr << "cbd: error: invalid_argument: " << message << "\n";
    writeParseErrorReport(app, argc, argv, message);
    return cbd::exitCode(cbd::ErrorCode::InvalidArgument);
  }

  // No output may land on an input file (a --json, -o or output folder naming one would replace
  // the user's mesh or anchors).
  {
    namespace fs = std::filesystem;
    std::vector<std::string> inputs, outputs;
    if (*cmdCheck) {
      inputs = {check.files.sourceMesh, check.files.targetMesh, check.files.sourceAnchors, check.files.targetAnchors};
      outputs = {check.jsonPath};
    } else if (*cmdLayout || *cmdMap) {
      const RunArgs& r = *cmdLayout ? layout : map;
      inputs = {r.mesh, r.anchors, r.target, r.targetAnchors};
      outputs = {r.jsonPath};
      // Every file the job writes under the output folder (the job names them).
      const std::vector<std::string> files = *cmdLayout ? cbd::outputFiles(r.layoutJob()) : cbd::outputFiles(r.mapJob());
      outputs.insert(outputs.end(), files.begin(), files.end());
    } else if (*cmdSample) {
      inputs = {sample.mesh};
      outputs = {sample.out};
    }
    // The JSON report onto one of the command's own files (it would replace M_st, say).
    if (outputs.size() > 1 && !outputs[0].empty() && outputs[0] != "-") {
      // Compared only where both paths resolve (a failure gives an empty path for each).
      std::error_code reportError;
      const fs::path report = fs::weakly_canonical(outputs[0], reportError);
      for (size_t k = 1; k < outputs.size() && !reportError; ++k)
        if (std::error_code ec; report == fs::weakly_canonical(outputs[k], ec) && !ec) {
          std::cerr << "cbd: error: invalid_argument: --json '" << outputs[0] << "' is one of the files the command "
                    << "writes: choose another path for the report\n";
          return cbd::exitCode(cbd::ErrorCode::InvalidArgument);
        }
    }
    // An output that exists and is the same file as an input (through any path, symlink or
    // hard link) would replace it; one that does not exist cannot be an input.
    for (const std::string& in : inputs) {
      if (in.empty()) continue;
      bool clash = false;
      for (const std::string& o : outputs) clash = clash || cbd::sameFile(in, o);
      if (clash) {
        std::cerr << "cbd: error: invalid_argument: an output would overwrite the input '" << in
                  << "': choose another output path\n";
        return cbd::exitCode(cbd::ErrorCode::InvalidArgument);
      }
    }
  }
  // `--json -`: the report alone on stdout, the log on stderr.
  const std::string* jsonPath = *cmdCheck ? &check.jsonPath : *cmdLayout ? &layout.jsonPath : *cmdMap ? &map.jsonPath : nullptr;
  if (jsonPath && *jsonPath == "-") {
    std::fflush(stdout);
    jsonStdout = ::dup(STDOUT_FILENO);
    if (jsonStdout < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) jsonStdout = -1;
  }
  try {
    if (*cmdCheck) return runCheck(check);
    if (*cmdLayout) return runLayout(layout);
    if (*cmdMap) return runMap(map);
    if (*cmdSample) return runSample(sample);
    if (*cmdCodes) {
      int n = 0;
      const cbd::ErrorCode* codes = cbd::allErrorCodes(n);
      for (int i = 0; i < n; ++i)
        std::printf("%3d  %-26s %s\n", cbd::exitCode(codes[i]), cbd::errorCodeName(codes[i]),
                    cbd::errorCodeDescription(codes[i]));
      return 0;
    }
  } catch (const std::bad_alloc&) {
    std::cerr << "cbd: error: internal_error: out of memory\n";
    return cbd::exitCode(cbd::ErrorCode::InternalError);
  } catch (const std::exception& e) {
    std::cerr << "cbd: error: internal_error: " << e.what() << " (please report this)\n";
    return cbd::exitCode(cbd::ErrorCode::InternalError);
  }
  return 0;
}
