// cbd: command-line front end. Arguments -> options -> core -> files -> exit code.
// Every failure is one line on stderr and a distinct exit code (see README, "Exit codes").

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cbd/anchor_sampling.h"
#include "cbd/layout_io.h"
#include "cbd/map_io.h"
#include "cbd/pipeline.h"
#include "cbd/validate_input.h"

namespace {

using nlohmann::json;

json meshJson(const cbd::MeshReport& m) {
  return json{{"vertices", m.vertices},
              {"faces", m.faces},
              {"genus", m.genus},
              {"unreferenced_vertices", m.unreferencedVertices},
              {"bbox_diagonal", m.bboxDiagonal},
              {"enclosed_volume", m.enclosedVolume},
              {"warnings", m.warnings}};
}

/// With `--json -`: the real standard output, kept for the report alone, while the human-readable
/// log goes to standard error (so that stdout parses as JSON).
int jsonStdout = -1;
/// The output folders this run created, innermost first; a failed run removes those still empty.
std::vector<std::filesystem::path> createdOutputFolders;

bool writeJson(const std::string& path, const json& j) {
  if (path.empty()) return true;
  if (path == "-") {
    const std::string text = j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
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
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path tmp = cbd::writeTarget(path);
  {
    std::ofstream out(tmp);
    if (!out) return false;
    out << j.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
    if (!out.good()) return false;
  }
  if (tmp == target) return true;  // a device, written in place
  std::error_code ec, ignored;
  fs::rename(tmp, target, ec);  // fails onto a folder, which is reported as such
  if (ec) fs::remove(tmp, ignored);
  return !ec;
}

/// Whether a new file can be created in `dir` (a probe file made by mkstemp, removed at once):
/// a permission check that holds for root, read-only mounts and pseudo file systems alike.
bool canCreateIn(const std::filesystem::path& dir) {
  std::string probe = (dir / ".cbd-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) return false;
  ::close(fd);
  ::unlink(probe.c_str());
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
      const json earlier = json::parse(existing, nullptr, /*allow_exceptions=*/false);
      if (!fs::is_regular_file(path, ec) || !earlier.is_object() || !earlier.contains("status")) return;
    }
    json j;
    j["status"] = cbd::errorCodeName(cbd::ErrorCode::InvalidArgument);
    j["message"] = message;
    writeJson(path, j);
    return;
  }
}

/// Before the computation (so that a run does not compute for minutes and then fail to save):
/// create the output folder when missing and check that it takes new files.
cbd::Status prepareOutputFolder(const std::string& outDir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(outDir, ec) && !fs::is_directory(outDir, ec))
    return cbd::Status::error(cbd::ErrorCode::OutputError, "output folder '" + outDir + "' is a file: choose another --out");
  // The folders that do not exist yet, innermost first ("a/b/.." creates a and a/b).
  std::vector<fs::path> missing;
  for (fs::path p = fs::absolute(outDir, ec); !p.empty() && p != p.parent_path() && !fs::exists(p, ec);
       p = p.parent_path()) {
    const std::string name = p.filename().string();
    if (!name.empty() && name != "." && name != "..") missing.push_back(p);
  }
  std::error_code created;
  fs::create_directories(outDir, created);
  if (!fs::is_directory(outDir, ec))
    return cbd::Status::error(cbd::ErrorCode::OutputError,
                              "cannot create output folder '" + outDir + "'" +
                                  (created ? " (" + created.message() + ")" : "") + ": choose --out under a writable folder");
  createdOutputFolders = missing;
  if (!canCreateIn(outDir))
    return cbd::Status::error(cbd::ErrorCode::OutputError,
                              "cannot write into output folder '" + outDir + "': check its permissions, or choose another --out");
  return cbd::Status::success();
}

/// The same for the JSON report (after the output folder, which may hold it): its folder exists
/// and takes new files, and the path is not a folder.
cbd::Status checkReportPath(const std::string& jsonPath) {
  namespace fs = std::filesystem;
  if (jsonPath.empty() || jsonPath == "-") return cbd::Status::success();
  std::error_code ec;
  const fs::path report(jsonPath);
  if (cbd::writeTarget(jsonPath) == jsonPath) return cbd::Status::success();  // a device: written in place
  const fs::path folder = report.parent_path().empty() ? fs::path(".") : report.parent_path();
  if (fs::is_directory(report, ec) || !fs::is_directory(folder, ec) || !canCreateIn(folder))
    return cbd::Status::error(cbd::ErrorCode::OutputError,
                              "cannot write JSON report '" + jsonPath +
                                  "' (check that its folder exists and is writable, and that it does not name a folder)");
  return cbd::Status::success();
}

int finish(const cbd::Status& status, json& j, const std::string& jsonPath) {
  j["status"] = cbd::errorCodeName(status.code);
  j["message"] = status.message;
  const bool reported = writeJson(jsonPath, j);
  // The run's own error first, also when the report cannot tell it.
  if (!status.ok()) std::cerr << "cbd: error: " << cbd::errorCodeName(status.code) << ": " << status.message << "\n";
  // A failed run leaves no empty output folder of its own making behind.
  if (!status.ok())
    for (const std::filesystem::path& dir : createdOutputFolders) {
      std::error_code ec;
      if (!std::filesystem::is_empty(dir, ec) || ec || !std::filesystem::remove(dir, ec)) break;
    }
  if (!reported) {
    std::cerr << "cbd: error: output_error: cannot write JSON report '" << jsonPath
              << "' (check that its folder exists and is writable, and that it does not name a folder)\n";
    return cbd::exitCode(cbd::ErrorCode::OutputError);
  }
  return cbd::exitCode(status.code);
}

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

struct PairArgs {
  cbd::InputFiles files;
  double snapTolerance = 0.01;
  std::string jsonPath;
};

void addPairOptions(CLI::App* cmd, PairArgs& a) {
  cmd->add_option("--source,-s", a.files.sourceMesh, "source mesh (.ply, .off, .obj, .stl)")->required();
  cmd->add_option("--target,-t", a.files.targetMesh, "target mesh (.ply, .off, .obj, .stl)")->required();
  cmd->add_option("--source-anchors", a.files.sourceAnchors,
                  "source anchors: MeshLab PickPoints .pp, 'index [x y z]' lines, or 'name x y z' lines")
      ->required();
  cmd->add_option("--target-anchors", a.files.targetAnchors, "target anchors, same formats; matched by name")
      ->required();
  cmd->add_option("--snap-tolerance", a.snapTolerance,
                  "largest allowed anchor-to-vertex distance, as a fraction of the bounding-box diagonal")
      ->capture_default_str()
      ->check(finiteRange(0.0, 1.0));
  cmd->add_option("--json", a.jsonPath, "also write a JSON report to this file ('-': to stdout, the log then goes to stderr)");
}

void printMesh(const char* role, const std::string& path, const cbd::MeshReport& m) {
  std::printf("%-7s %s: %d vertices, %d faces, genus %d\n", role, path.c_str(), m.vertices, m.faces, m.genus);
  for (const auto& w : m.warnings) std::printf("  warning: %s\n", w.c_str());
}

int runCheck(const PairArgs& a) {
  cbd::ValidationOptions opt;
  opt.snapTolerance = a.snapTolerance;
  cbd::LoadedInput in;
  cbd::loadAndValidate(a.files, opt, in);
  const cbd::InputReport& r = in.report;
  json j;
  j["source"] = meshJson(r.source);
  j["target"] = meshJson(r.target);
  j["source"]["anchors"] = r.anchors.size();
  j["target"]["anchors"] = r.anchors.size();
  if (r.status) {
    printMesh("source", a.files.sourceMesh, r.source);
    printMesh("target", a.files.targetMesh, r.target);
    double worstS = 0, worstT = 0;
    json list = json::array();
    for (int k = 0; k < r.anchors.size(); ++k) {
      const auto& s = r.anchors.source[k];
      const auto& t = r.anchors.target[k];
      worstS = std::max(worstS, s.snapDistance);
      worstT = std::max(worstT, t.snapDistance);
      list.push_back({{"name", r.anchors.names[k]},
                      {"source_vertex", s.vertex},
                      {"target_vertex", t.vertex},
                      {"source_snap", s.snapDistance},
                      {"target_snap", t.snapDistance}});
    }
    j["anchors"] = list;
    std::printf("anchors %d pairs matched by name; largest snap distance %.3g%% (source), %.3g%% (target) "
                "of the bbox diagonal\n",
                r.anchors.size(), 100 * worstS, 100 * worstT);
    std::printf("ok: the pair can be processed\n");
  }
  return finish(r.status, j, a.jsonPath);
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
};

double elapsed(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Both output checks before a run; the exit code when one fails. A report that can be written
/// still tells why the output folder cannot.
std::optional<int> prepareOutputs(const RunArgs& a, json& j) {
  if (cbd::Status s = prepareOutputFolder(a.out); !s) return finish(s, j, a.jsonPath);
  if (cbd::Status s = checkReportPath(a.jsonPath); !s) return finish(s, j, "");
  return std::nullopt;
}

/// The pipeline's options from the command line; `names`: the anchors' names, for messages.
cbd::CrossParameterizationOptions pipelineOptions(const RunArgs& a, const std::vector<std::string>& names = {}) {
  cbd::CrossParameterizationOptions o;
  o.anchorNames = names;
  o.method = a.method == "greedy" ? cbd::LayoutMethod::Greedy : cbd::LayoutMethod::Voronoi;
  o.edgeNodes.minEdgeNodes = a.singleEdgeNode ? 1 : a.minEdgeNodes;
  o.edgeNodes.adaptive = !a.singleEdgeNode;
  o.smoothing.iterations = a.smooth;
  o.straightening.rounds = a.straighten;
  o.untangle = !a.noUntangle;
  o.mapStage = a.mapStage == "optimize" ? cbd::MapStage::Optimize : cbd::MapStage::Untangle;
  o.flipPaths = a.flipPaths;
  return o;
}

/// Load and validate a source/target pair; fills the JSON input keys.
cbd::Status loadPair(const RunArgs& a, cbd::LoadedInput& in, std::vector<int>& sa, std::vector<int>& ta, json& j) {
  cbd::ValidationOptions vopt;
  vopt.snapTolerance = a.snapTolerance;
  cbd::loadAndValidate({a.mesh, a.target, a.anchors, a.targetAnchors}, vopt, in);
  j["source"] = meshJson(in.report.source);
  j["target"] = meshJson(in.report.target);
  if (!in.report.status) return in.report.status;
  j["source"]["anchors"] = j["target"]["anchors"] = in.report.anchors.size();
  for (const auto& s : in.report.anchors.source) sa.push_back(s.vertex);
  for (const auto& s : in.report.anchors.target) ta.push_back(s.vertex);
  for (const auto* m : {&in.report.source, &in.report.target})
    for (const auto& w : m->warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());
  return cbd::Status::success();
}

json layoutJson(const cbd::LayoutPair& p) {
  json l = {{"edges", p.source.edges.size()},
            {"patches", p.source.patches.size()},
            {"multi_linkages", p.source.multipleLinkages()},
            {"detour", p.detour},
            {"warnings", p.warnings}};
  if (p.method == cbd::LayoutMethod::Voronoi) {
    // "diagram": whose Voronoi diagram gave the layout (the target's when the source's detoured).
    l["diagram"] = p.reversed ? "target" : "source";
    l["same_surface"] = p.sameSurface;
    if (p.triedReverse) l["other_direction_detour"] = p.reverseDetour;
    l["flips"] = p.flips;
    l["cut_paths"] = p.sourceStats.cutPaths;
    l["triangulation_paths"] = p.sourceStats.triangulationPaths;
    l["removed_paths"] = p.sourceStats.removedPaths;
    l["rejected_paths"] = p.sourceStats.rejectedPaths;
    l["target"] = {{"in_clusters", p.targetStats.embeddedInClusters},
                   {"in_region", p.targetStats.embeddedInRegion},
                   {"postponements", p.targetStats.postponements},
                   {"waited_for_passed_anchors", p.targetStats.waitedForPassedAnchors},
                   {"rejected_paths", p.targetStats.rejectedPaths}};
  } else {
    const auto& g = p.greedyStats;
    l["greedy"] = {{"candidates", g.candidates}, {"tried", g.tried},         {"accepted", g.accepted},
                   {"rejected", g.rejected},     {"completion_paths", g.completionPaths},
                   {"completion_rejected", g.completionRejected}, {"flips", g.flips}};
  }
  return l;
}

json timesJson(const cbd::StageTimes& t) {
  return {{"voronoi", t.voronoi},         {"source_layout", t.sourceLayout},
          {"target_layout", t.targetLayout}, {"straighten", t.straighten},
          {"parameterization", t.parameterization},
          {"untangle", t.untangle},       {"distortion", t.distortion},   {"total", t.total}};
}

void printLayout(const cbd::LayoutPair& p) {
  for (const auto& w : p.warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());
  if (p.method == cbd::LayoutMethod::Voronoi) {
    std::printf("layout  voronoi: %zu edges (%d across Voronoi cuts, %d triangulating), %zu patches, %d multiple linkages\n",
                p.source.edges.size(), p.sourceStats.cutPaths - p.sourceStats.removedPaths,
                p.sourceStats.triangulationPaths, p.source.patches.size(), p.source.multipleLinkages());
    if (p.sameSurface)
      std::printf("        target: the source itself (same vertices, faces and anchors): the same layout\n");
    else
      std::printf("        %s: %d paths inside the two clusters, %d in the whole region; detour %.2f\n",
                  p.reversed ? "traced on the source" : "target", p.targetStats.embeddedInClusters,
                  p.targetStats.embeddedInRegion, p.detour);
    if (p.reversed)
      std::printf("        (the layout traced from the source's diagram detoured by %.2f: this one comes from the "
                  "target's Voronoi diagram)\n", p.reverseDetour);
    if (p.flips > 0) std::printf("        path flipping: %d edges replaced on both surfaces\n", p.flips);
  } else {
    const auto& g = p.greedyStats;
    std::printf("layout  greedy: %zu edges, %zu patches; %d candidate pairs, %d traced, %d accepted, %d rejected, "
                "%d completion paths (%d undone), %d flips\n",
                p.source.edges.size(), p.source.patches.size(), g.candidates, g.tried, g.accepted, g.rejected,
                g.completionPaths, g.completionRejected, g.flips);
  }
}

int runSingleLayout(const RunArgs& a) {
  json j;
  const auto t0 = std::chrono::steady_clock::now();
  cbd::Mesh mesh;
  cbd::LoadResult lr = cbd::loadMesh(a.mesh, mesh);
  if (!lr.status) return finish(lr.status, j, a.jsonPath);
  const cbd::IndexedMesh source = cbd::toIndexed(mesh);
  cbd::MeshReport rep = cbd::validateMesh(source, "source", lr.hadPolygons);
  cbd::nameMeshFile(rep, a.mesh);
  rep.warnings.insert(rep.warnings.end(), lr.warnings.begin(), lr.warnings.end());
  j["source"] = meshJson(rep);
  if (!rep.status) return finish(rep.status, j, a.jsonPath);
  for (const auto& w : rep.warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());
  const cbd::AnchorSet set = cbd::readAnchors(a.anchors);
  if (!set.status) return finish(set.status, j, a.jsonPath);
  std::vector<cbd::SnappedAnchor> snapped;
  if (cbd::Status s = cbd::snapAnchors(source, set, a.snapTolerance, "source", snapped); !s) return finish(s, j, a.jsonPath);
  j["source"]["anchors"] = snapped.size();
  if (snapped.size() < 3)
    return finish(cbd::Status::error(cbd::ErrorCode::TooFewAnchors,
                                     a.anchors + ": " + std::to_string(snapped.size()) + " anchors" +
                                         (set.skippedInactive > 0 ? " (and " + std::to_string(set.skippedInactive) +
                                                                        " inactive points, active=\"0\", left out)"
                                                                  : std::string()) +
                                         "; a layout needs at least 3"),
                  j, a.jsonPath);
  std::vector<int> anchors;
  cbd::SourceLayoutOptions opt;
  for (const auto& s : snapped) anchors.push_back(s.vertex), opt.anchorNames.push_back(s.name);
  if (const std::optional<int> rc = prepareOutputs(a, j)) return *rc;
  opt.edgeNodes = pipelineOptions(a).edgeNodes;
  const cbd::SourceLayoutResult r = cbd::buildSourceLayout(source, anchors, opt);
  j["timing_s"] = {{"voronoi", r.voronoiSeconds}, {"source_layout", r.layoutSeconds}};
  if (!r.status) return finish(r.status, j, a.jsonPath);
  if (const cbd::LayoutCheck c = cbd::validateLayout(r.layout, rep.eulerCharacteristic); !c.status)
    return finish(c.status, j, a.jsonPath);
  if (cbd::Status s = cbd::writeLayout(r.layout, a.out); !s) return finish(s, j, a.jsonPath);
  j["layout"] = {{"edges", r.layout.edges.size()},       {"patches", r.layout.patches.size()},
                 {"multi_linkages", r.layout.multipleLinkages()}, {"cut_paths", r.cutPaths},
                 {"triangulation_paths", r.triangulationPaths},   {"removed_paths", r.removedPaths},
                 {"rejected_paths", r.rejectedPaths}};
  j["timing_s"]["total"] = elapsed(t0);
  std::printf("source  %s: %d vertices, %d faces, genus %d, %zu anchors\n", a.mesh.c_str(), rep.vertices, rep.faces,
              rep.genus, anchors.size());
  std::printf("layout  %zu edges (%d across Voronoi cuts, %d triangulating), %zu patches, %d multiple linkages\n",
              r.layout.edges.size(), r.cutPaths - r.removedPaths, r.triangulationPaths, r.layout.patches.size(),
              r.layout.multipleLinkages());
  std::printf("time    voronoi %.3f s, layout %.3f s\n", r.voronoiSeconds, r.layoutSeconds);
  std::printf("wrote   %s/{layout,paths,clusters}.ply\n", a.out.c_str());
  return finish(cbd::Status::success(), j, a.jsonPath);
}

int runLayout(const RunArgs& a) {
  if (a.target.empty()) {
    if (a.method == "greedy") {
      json j;
      return finish(cbd::Status::error(cbd::ErrorCode::InvalidArgument,
                                       "--method greedy builds both layouts at once: give --target and --target-anchors"),
                    j, a.jsonPath);
    }
    return runSingleLayout(a);
  }
  json j;
  j["method"] = a.method;
  const auto t0 = std::chrono::steady_clock::now();
  cbd::LoadedInput in;
  std::vector<int> sa, ta;
  if (cbd::Status s = loadPair(a, in, sa, ta, j); !s) return finish(s, j, a.jsonPath);
  if (const std::optional<int> rc = prepareOutputs(a, j)) return *rc;
  cbd::LayoutPair p = cbd::buildLayouts(in.source, sa, in.target, ta, in.report.source.eulerCharacteristic,
                                         pipelineOptions(a, in.report.anchors.names));
  p.times.total = elapsed(t0);
  j["timing_s"] = timesJson(p.times);
  if (!p.status) return finish(p.status, j, a.jsonPath);
  j["layout"] = layoutJson(p);
  if (cbd::Status s = cbd::writeLayout(p.source, a.out + "/" + cbd::kSourceLayoutFolder); !s) return finish(s, j, a.jsonPath);
  if (cbd::Status s = cbd::writeLayout(p.target, a.out + "/" + cbd::kTargetLayoutFolder); !s) return finish(s, j, a.jsonPath);
  printLayout(p);
  std::printf("time    voronoi %.3f s, source layout %.3f s, target layout %.3f s\n", p.times.voronoi,
              p.times.sourceLayout, p.times.targetLayout);
  std::printf("wrote   %s/{source,target}/{layout,paths%s}.ply\n", a.out.c_str(),
              p.method == cbd::LayoutMethod::Voronoi ? ",clusters" : "");
  return finish(cbd::Status::success(), j, a.jsonPath);
}

int runMap(const RunArgs& a) {
  json j;
  j["method"] = a.method;
  const auto t0 = std::chrono::steady_clock::now();
  cbd::LoadedInput in;
  std::vector<int> sa, ta;
  if (cbd::Status s = loadPair(a, in, sa, ta, j); !s) return finish(s, j, a.jsonPath);
  if (const std::optional<int> rc = prepareOutputs(a, j)) return *rc;
  cbd::CrossParameterizationResult r =
      cbd::crossParameterize(in.source, sa, in.target, ta, in.report.source.eulerCharacteristic,
                             pipelineOptions(a, in.report.anchors.names));
  r.times.total = elapsed(t0);
  j["timing_s"] = timesJson(r.times);
  if (!r.status) return finish(r.status, j, a.jsonPath);
  j["layout"] = layoutJson(r.layouts);
  if (a.straighten > 0) {
    auto side = [](const cbd::PathStraighteningResult& s) {
      return json{{"straightened", s.straightened}, {"skipped", s.skipped}, {"splits", s.splits},
                  {"length_before", s.lengthBefore}, {"length_after", s.lengthAfter}};
    };
    j["straighten"] = {{"rounds", a.straighten}, {"source", side(r.straightenSource)},
                       {"target", side(r.straightenTarget)}, {"failed", r.straightenFailed}};
    for (const auto* s : {&r.straightenSource, &r.straightenTarget})
      if (!s->status) j["straighten"]["error"] = s->status.message;
  }
  const auto& m = r.metrics;
  if (a.smooth > 0)
    j["smoothing"] = {{"iterations", a.smooth}, {"moves", r.smoothing.moves}, {"rejected", r.smoothing.rejected},
                      {"flipped_before", r.smoothing.flippedBefore}, {"flipped_after", r.smoothing.flippedAfter}};
  const bool optimized = !a.noUntangle && a.mapStage == "optimize";
  if (optimized) {
    const auto& o = r.optimization;
    j["optimize"] = {{"iterations", o.iterations},      {"converged", o.converged},  {"energy_before", o.energyBefore},
                     {"energy_after", o.energyAfter}, {"injective", o.injective}};
  } else if (!a.noUntangle) {
    const auto &u = r.untangleSource, &w = r.untangleTarget;
    j["untangle"] = {{"flipped_before", u.flippedBefore},         {"flipped_after", u.flippedAfter},
                     {"moved_vertices", u.movedVertices},         {"inverse_flipped_before", w.flippedBefore},
                     {"inverse_flipped_after", w.flippedAfter},   {"inverse_moved_vertices", w.movedVertices},
                     {"attempts", u.attempts},                    {"inverse_attempts", w.attempts}};
  }
  j["metrics"] = {{"e_ang", m.eAng},     {"e_ang_deg", m.eAngDegrees}, {"e_l2", m.eL2},
                  {"e_l2_inverse", m.eL2Inverse}, {"flipped", m.flipped}, {"degenerate", m.degenerate}};
  {
    const auto& c = r.composedMetrics;
    j["metrics"]["composed"] = {{"e_ang", c.eAng},         {"e_ang_deg", c.eAngDegrees}, {"e_l2", c.eL2},
                                {"e_l2_inverse", c.eL2Inverse}, {"flipped", c.flipped},      {"degenerate", c.degenerate}};
  }
  // M_st with the target's attributes, M_ts with the source's.
  const cbd::DistortionMetrics inverse =
      cbd::computeDistortion(in.target, r.map.targetImage, in.source, r.map.targetToSource);
  cbd::TransferOptions toSource{in.targetLoad.hasVertexColor, in.targetLoad.hasVertexQuality, in.targetLoad.hasVertexTexCoord};
  cbd::TransferOptions toTarget{in.sourceLoad.hasVertexColor, in.sourceLoad.hasVertexQuality, in.sourceLoad.hasVertexTexCoord};
  cbd::Mesh mst, mts;
  cbd::buildMappedMesh(in.sourceMesh, r.map.sourceImage, r.map.sourceToTarget, in.targetMesh, toSource,
                       m.faceStretch, mst);
  cbd::buildMappedMesh(in.targetMesh, r.map.targetImage, r.map.targetToSource, in.sourceMesh, toTarget,
                       inverse.faceStretch, mts);
  cbd::SavePlyOptions po;
  po.faceColor = po.faceQuality = true;
  po.vertexColor = toSource.vertexColor;
  po.vertexQuality = toSource.vertexQuality;
  po.vertexTexCoord = toSource.vertexTexCoord;
  const std::string dir = a.out;
  if (cbd::Status s = cbd::savePly(dir + "/" + cbd::kMstFile, mst, po); !s) return finish(s, j, a.jsonPath);
  po.vertexColor = toTarget.vertexColor;
  po.vertexQuality = toTarget.vertexQuality;
  po.vertexTexCoord = toTarget.vertexTexCoord;
  if (cbd::Status s = cbd::savePly(dir + "/" + cbd::kMtsFile, mts, po); !s) return finish(s, j, a.jsonPath);
  if (cbd::Status s = cbd::writeCorrespondence(dir + "/" + cbd::kCorrespondenceFile, r.map.sourceToTarget, r.map.sourceImage); !s)
    return finish(s, j, a.jsonPath);
  if (cbd::Status s = cbd::writeLayout(r.layouts.source, dir + "/" + cbd::kSourceLayoutFolder); !s) return finish(s, j, a.jsonPath);
  if (cbd::Status s = cbd::writeLayout(r.layouts.target, dir + "/" + cbd::kTargetLayoutFolder); !s) return finish(s, j, a.jsonPath);
  int staleFrames = 0;
  if (a.morph > 0)
    if (cbd::Status s = cbd::writeMorph(dir, in.sourceMesh, r.map.sourceImage, sa, a.morph, &staleFrames); !s)
      return finish(s, j, a.jsonPath);
  printLayout(r.layouts);
  if (a.straighten > 0) {
    const auto &s = r.straightenSource, &t = r.straightenTarget;
    if (r.straightenFailed)
      std::printf("straighten failed (%s): both layouts kept as traced\n",
                  (!s.status ? s.status : t.status).message.c_str());
    else
      std::printf("straighten %d round%s: %d / %d paths straightened (source / target), total length %.4g -> %.4g / "
                  "%.4g -> %.4g\n",
                  a.straighten, a.straighten == 1 ? "" : "s", s.straightened, t.straightened, s.lengthBefore,
                  s.lengthAfter, t.lengthBefore, t.lengthAfter);
  }
  if (a.smooth > 0)
    std::printf("smooth  %d sweep%s over M_st: %d moves kept, %d rejected (a flip or outside the chart), flipped %d -> %d\n",
                a.smooth, a.smooth == 1 ? "" : "s", r.smoothing.moves, r.smoothing.rejected, r.smoothing.flippedBefore,
                r.smoothing.flippedAfter);
  std::printf("map     E_ang %.4f (%.2f deg), E_L2 %.4f (inverse %.4f), %d flipped, %d degenerate triangles\n", m.eAng,
              m.eAngDegrees, m.eL2, m.eL2Inverse, m.flipped, m.degenerate);
  if (!a.noUntangle)
    std::printf("composed E_ang %.4f, E_L2 %.4f, %d flipped (the map before untangling)\n", r.composedMetrics.eAng,
                r.composedMetrics.eL2, r.composedMetrics.flipped);
  if (optimized)
    std::printf("optimize %d iterations%s, injective in the base domain; M_ts (its inverse): %d flipped\n",
                r.optimization.iterations, r.optimization.converged ? "" : " (not converged)", inverse.flipped);
  else if (!a.noUntangle)
    std::printf("untangle flipped triangles of M_st %d -> %d (%d vertices moved), of M_ts %d -> %d\n",
                r.untangleSource.flippedBefore, r.untangleSource.flippedAfter, r.untangleSource.movedVertices,
                r.untangleTarget.flippedBefore, r.untangleTarget.flippedAfter);
  std::printf("time    voronoi %.3f s, source layout %.3f s, target layout %.3f s, straighten %.3f s, "
              "parameterization %.3f s, untangle %.3f s, total %.3f s\n",
              r.times.voronoi, r.times.sourceLayout, r.times.targetLayout, r.times.straighten, r.times.parameterization,
              r.times.untangle, r.times.total);
  std::printf("wrote   %s/mst.ply (source connectivity on the target; face quality = stretch), %s/mts.ply,\n"
              "        %s/correspondence.txt, %s/{source,target}/ layouts%s\n",
              dir.c_str(), dir.c_str(), dir.c_str(), dir.c_str(), a.morph > 0 ? ", morph_*.ply" : "");
  if (staleFrames > 0)
    std::printf("removed %d morph frame%s after %s of an earlier, longer sequence\n", staleFrames,
                staleFrames == 1 ? "" : "s", cbd::morphFileName(a.morph - 1).c_str());
  return finish(cbd::Status::success(), j, a.jsonPath);
}

struct SampleArgs {
  std::string mesh, out;
  int count = 0;
  int seed = 0;
};

int runSample(const SampleArgs& a) {
  json j;
  cbd::Mesh mesh;
  cbd::LoadResult lr = cbd::loadMesh(a.mesh, mesh);
  if (!lr.status) return finish(lr.status, j, "");
  const cbd::IndexedMesh im = cbd::toIndexed(mesh);
  // Anchors are for meshes `map` accepts; a NaN coordinate would be written as a "nan" anchor.
  cbd::MeshReport rep = cbd::validateMesh(im, "", lr.hadPolygons);
  cbd::nameMeshFile(rep, a.mesh);
  if (!rep.status) return finish(rep.status, j, "");
  rep.warnings.insert(rep.warnings.end(), lr.warnings.begin(), lr.warnings.end());
  for (const auto& w : rep.warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());
  if (a.seed < 0 || a.seed >= im.vertexCount())
    return finish(cbd::Status::error(cbd::ErrorCode::InvalidArgument,
                                     "--seed " + std::to_string(a.seed) + " is not a vertex of '" + a.mesh + "' (0.." +
                                         std::to_string(im.vertexCount() - 1) + ")"),
                  j, "");
  // The sampling would start elsewhere, silently, from a vertex no face uses.
  if (std::none_of(im.faces.begin(), im.faces.end(), [&](const auto& f) { return f[0] == a.seed || f[1] == a.seed || f[2] == a.seed; }))
    return finish(cbd::Status::error(cbd::ErrorCode::InvalidArgument,
                                     "--seed " + std::to_string(a.seed) + " is an unreferenced vertex of '" + a.mesh +
                                         "' (no face uses it): choose a vertex of the surface"),
                  j, "");
  const std::vector<int> vs = cbd::farthestPointSampling(im, a.count, a.seed);
  if (static_cast<int>(vs.size()) < a.count)
    std::fprintf(stderr, "cbd: warning: '%s' has only %zu vertices on its surface: %zu anchors written, not %d\n",
                 a.mesh.c_str(), vs.size(), vs.size(), a.count);
  std::vector<cbd::Anchor> anchors;
  for (size_t k = 0; k < vs.size(); ++k) {
    cbd::Anchor an;
    an.name = "a" + std::to_string(k + 1);
    an.position = im.positions[vs[k]];
    anchors.push_back(an);
  }
  const cbd::Status s = cbd::writePickedPoints(a.out, anchors, std::filesystem::path(a.mesh).filename().string());
  if (s) std::printf("wrote %s to %s\n", cbd::counted(static_cast<long long>(anchors.size()), "anchor", "anchors").c_str(), a.out.c_str());
  return finish(s, j, "");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "cbd: common base domains by cues from the Voronoi diagram of anchor points, and the\n"
      "cross-parameterization between two closed triangle meshes built on them\n"
      "(Kwok, Zhang & Wang, Graphical Models 2012)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cbd 0.1.0");

  PairArgs check;
  CLI::App* cmdCheck = app.add_subcommand(
      "check",
      "Validate a source/target mesh pair and their anchors; print vertices, faces, genus, anchors "
      "and snap distances. Exit 0 when the pair can be processed, else a distinct code per problem.");
  addPairOptions(cmdCheck, check);

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
        ->check(CLI::Range(1, 16));
    cmd->add_flag("--single-edge-node", r.singleEdgeNode, "one edge node per edge, no adaptivity (the paper's E1 setting)")
        ->excludes(b);
    cmd->add_option("--snap-tolerance", r.snapTolerance, "largest anchor snap distance (fraction of bbox diagonal)")
        ->capture_default_str()
        ->check(finiteRange(0.0, 1.0));
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
      ->check(CLI::Range(0, 1000));
  cmdMap->add_option("--straighten", map.straighten,
                     "N rounds straightening every path of both layouts inside its two patches (the diagonal of "
                     "their quadrilateral mapped onto a square; the same for either method), before the patches "
                     "are parameterized; 0: the paths as traced; at most 8: every round splits mesh edges along "
                     "the paths, the time grows steeply with the rounds, and the paths settle within a few)")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  cmdMap->add_option("--map-stage", map.mapStage,
                     "untangle: remove flipped triangles of M_st and M_ts, then polish (the default); optimize "
                     "(experimental): M_st optimized in the base domain by Newton's method, injective there, "
                     "M_ts its exact inverse, but with flipped triangles left (see README)")
      ->capture_default_str()
      ->check(CLI::IsMember({"untangle", "optimize"}));
  cmdMap->add_flag("--no-untangle", map.noUntangle,
                   "keep the composed map as it is: do not move the images of the vertices of flipped M_st / M_ts "
                   "triangles over the target (the default removes most flips, then polishes the map; see README)");
  cmdMap->add_option("--morph", map.morph, "also write K meshes OUT/morph_000.ply ... blending the source (fitted onto the target by its anchors) into M_st; "
                     "later frames of an earlier, longer sequence in OUT are removed")
      ->check(CLI::Range(2, 1000));

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
      // Every file cbd writes under the output folder (the names the writers use): the layouts
      // (in it for a single surface, else in source/ and target/), and for `map` M_st, M_ts,
      // the correspondence and the morph frames.
      const fs::path out(r.out);
      const std::vector<fs::path> dirs = *cmdLayout && r.target.empty()
                                             ? std::vector<fs::path>{out}
                                             : std::vector<fs::path>{out / cbd::kSourceLayoutFolder,
                                                                     out / cbd::kTargetLayoutFolder};
      for (const fs::path& d : dirs)
        for (const char* name : {cbd::kLayoutFile, cbd::kPathsFile, cbd::kClustersFile}) outputs.push_back((d / name).string());
      if (*cmdMap) {
        for (const char* name : {cbd::kMstFile, cbd::kMtsFile, cbd::kCorrespondenceFile}) outputs.push_back((out / name).string());
        for (int k = 0; k < map.morph; ++k) outputs.push_back((out / cbd::morphFileName(k)).string());
        // And the later frames of an earlier sequence, which writeMorph removes.
        if (map.morph > 0)
          for (const std::string& stale : cbd::staleMorphFrames(out.string(), map.morph)) outputs.push_back(stale);
      }
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
      for (const std::string& o : outputs) {
        std::error_code ec;
        if (!o.empty() && o != "-" && fs::exists(o, ec) && fs::equivalent(in, o, ec)) clash = true;
      }
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
