// cbd: command-line front end. Arguments -> options -> core -> files -> exit code.
// Every failure is one line on stderr and a distinct exit code (see README, "Exit codes").

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cbd/anchor_sampling.h"
#include "cbd/greedy_layout.h"
#include "cbd/layout_io.h"
#include "cbd/source_layout.h"
#include "cbd/target_layout.h"
#include "cbd/validate_input.h"

namespace {

using nlohmann::json;

json meshJson(const cbd::MeshReport& m) {
  return json{{"vertices", m.vertices},
              {"faces", m.faces},
              {"genus", m.genus},
              {"unreferenced_vertices", m.unreferencedVertices},
              {"bbox_diagonal", m.bboxDiagonal}};
}

bool writeJson(const std::string& path, const json& j) {
  if (path.empty()) return true;
  if (path == "-") {
    std::cout << j.dump(2) << "\n";
    return true;
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  {
    std::ofstream out(tmp);
    if (!out) return false;
    out << j.dump(2) << "\n";
    if (!out.good()) return false;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) fs::remove(tmp, ec);
  return !ec;
}

int finish(const cbd::Status& status, json& j, const std::string& jsonPath) {
  j["status"] = cbd::errorCodeName(status.code);
  j["message"] = status.message;
  if (!writeJson(jsonPath, j)) {
    std::cerr << "cbd: error: output_error: cannot write JSON report '" << jsonPath
              << "' (check that the folder exists and is writable)\n";
    return cbd::exitCode(cbd::ErrorCode::OutputError);
  }
  if (!status.ok()) {
    std::cerr << "cbd: error: " << cbd::errorCodeName(status.code) << ": " << status.message << "\n";
  }
  return cbd::exitCode(status.code);
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
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--json", a.jsonPath, "also write a JSON report to this file ('-' for stdout)");
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

struct LayoutArgs {
  std::string mesh, anchors, out, jsonPath;
  std::string target, targetAnchors;
  std::string method = "voronoi";
  int minEdgeNodes = 3;
  bool singleEdgeNode = false;
  double snapTolerance = 0.01;
};

double elapsed(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int runLayout(const LayoutArgs& a) {
  json j;
  const auto t0 = std::chrono::steady_clock::now();
  const bool pair = !a.target.empty();
  cbd::ValidationOptions vopt;
  vopt.snapTolerance = a.snapTolerance;
  cbd::IndexedMesh source, target;
  std::vector<int> sourceAnchors, targetAnchors;
  cbd::MeshReport sourceReport;
  if (pair) {
    cbd::LoadedInput in;
    cbd::loadAndValidate({a.mesh, a.target, a.anchors, a.targetAnchors}, vopt, in);
    j["source"] = meshJson(in.report.source);
    j["target"] = meshJson(in.report.target);
    if (!in.report.status) return finish(in.report.status, j, a.jsonPath);
    j["source"]["anchors"] = j["target"]["anchors"] = in.report.anchors.size();
    sourceReport = in.report.source;
    source = std::move(in.source);
    target = std::move(in.target);
    for (const auto& s : in.report.anchors.source) sourceAnchors.push_back(s.vertex);
    for (const auto& s : in.report.anchors.target) targetAnchors.push_back(s.vertex);
  } else {
    cbd::Mesh mesh;
    cbd::LoadResult lr = cbd::loadMesh(a.mesh, mesh);
    if (!lr.status) return finish(lr.status, j, a.jsonPath);
    source = cbd::toIndexed(mesh);
    sourceReport = cbd::validateMesh(source, "source", lr.hadPolygons, vopt);
    j["source"] = meshJson(sourceReport);
    if (!sourceReport.status) {
      sourceReport.status.message =
          "source mesh '" + a.mesh + "'" + sourceReport.status.message.substr(std::string("source mesh").size());
      return finish(sourceReport.status, j, a.jsonPath);
    }
    const cbd::AnchorSet set = cbd::readAnchors(a.anchors);
    if (!set.status) return finish(set.status, j, a.jsonPath);
    std::vector<cbd::SnappedAnchor> snapped;
    if (cbd::Status s = cbd::snapAnchors(source, set, a.snapTolerance, "source", snapped); !s)
      return finish(s, j, a.jsonPath);
    j["source"]["anchors"] = snapped.size();
    if (snapped.size() < 3) {
      return finish(cbd::Status::error(cbd::ErrorCode::TooFewAnchors,
                                       a.anchors + ": " + std::to_string(snapped.size()) +
                                           " anchors; a layout needs at least 3"),
                    j, a.jsonPath);
    }
    for (const auto& s : snapped) sourceAnchors.push_back(s.vertex);
  }
  for (const auto& w : sourceReport.warnings) std::fprintf(stderr, "cbd: warning: %s\n", w.c_str());

  cbd::SourceLayoutOptions opt;
  opt.edgeNodes.minEdgeNodes = a.singleEdgeNode ? 1 : a.minEdgeNodes;
  opt.edgeNodes.adaptive = !a.singleEdgeNode;
  j["method"] = a.method;
  if (a.method == "greedy") {
    if (!pair)
      return finish(cbd::Status::error(cbd::ErrorCode::InvalidArgument,
                                       "--method greedy builds both layouts at once: give --target and --target-anchors"),
                    j, a.jsonPath);
    cbd::GreedyLayoutOptions gopt;
    gopt.edgeNodes = opt.edgeNodes;
    const cbd::GreedyLayoutResult g = cbd::buildGreedyLayout(source, sourceAnchors, target, targetAnchors, gopt);
    j["timing_s"] = {{"candidates", g.candidateSeconds}, {"source_layout", g.candidateSeconds + g.layoutSeconds},
                     {"target_layout", 0.0}};
    j["greedy"] = {{"candidates", g.candidates}, {"tried", g.tried}, {"accepted", g.accepted},
                   {"rejected", g.rejected}, {"completion_paths", g.completionPaths}, {"flips", g.flips}};
    if (!g.status) return finish(g.status, j, a.jsonPath);
    for (const cbd::Layout* L : {&g.source, &g.target})
      if (const cbd::LayoutCheck c = cbd::validateLayout(*L, sourceReport.eulerCharacteristic); !c.status)
        return finish(c.status, j, a.jsonPath);
    j["layout"] = {{"edges", g.source.edges.size()}, {"patches", g.source.patches.size()},
                   {"multi_linkages", g.source.multipleLinkages()}};
    if (cbd::Status s = cbd::writeLayout(g.source, {}, a.out + "/source"); !s) return finish(s, j, a.jsonPath);
    if (cbd::Status s = cbd::writeLayout(g.target, {}, a.out + "/target"); !s) return finish(s, j, a.jsonPath);
    j["timing_s"]["total"] = elapsed(t0);
    std::printf("greedy  %d candidate pairs, %d traced, %d accepted, %d rejected, %d completion paths, %d flips\n",
                g.candidates, g.tried, g.accepted, g.rejected, g.completionPaths, g.flips);
    std::printf("layout  %zu edges, %zu patches; time %.3f s (all-pairs paths %.3f s)\n", g.source.edges.size(),
                g.source.patches.size(), g.candidateSeconds + g.layoutSeconds, g.candidateSeconds);
    std::printf("wrote   %s/{source,target}/{layout,paths}.ply\n", a.out.c_str());
    return finish(cbd::Status::success(), j, a.jsonPath);
  }
  const cbd::SourceLayoutResult r = cbd::buildSourceLayout(source, sourceAnchors, opt);
  j["timing_s"] = {{"voronoi", r.voronoiSeconds}, {"source_layout", r.layoutSeconds}};
  if (!r.status) return finish(r.status, j, a.jsonPath);
  if (const cbd::LayoutCheck c = cbd::validateLayout(r.layout, sourceReport.eulerCharacteristic); !c.status)
    return finish(c.status, j, a.jsonPath);
  j["layout"] = {{"edges", r.layout.edges.size()},
                 {"patches", r.layout.patches.size()},
                 {"multi_linkages", r.layout.multipleLinkages()},
                 {"cut_paths", r.cutPaths},
                 {"cut_paths_failed", r.cutPathsFailed},
                 {"triangulation_paths", r.triangulationPaths},
                 {"removed_paths", r.removedPaths}};
  cbd::TargetLayoutResult tr;
  if (pair) {
    cbd::TargetLayoutOptions topt;
    topt.edgeNodes = opt.edgeNodes;
    tr = cbd::buildTargetLayout(r.layout, target, targetAnchors, topt);
    j["timing_s"]["target_voronoi"] = tr.voronoiSeconds;
    j["timing_s"]["target_layout"] = tr.layoutSeconds;
    if (!tr.status) return finish(tr.status, j, a.jsonPath);
    if (const cbd::LayoutCheck c = cbd::validateLayout(tr.layout, sourceReport.eulerCharacteristic); !c.status)
      return finish(c.status, j, a.jsonPath);
    j["layout"]["target"] = {{"in_clusters", tr.embeddedInClusters},
                             {"in_region", tr.embeddedInRegion},
                             {"postponements", tr.postponements},
                             {"rejected_paths", tr.rejectedPaths}};
  }
  const std::string srcDir = pair ? a.out + "/source" : a.out;
  if (cbd::Status s = cbd::writeLayout(r.layout, r.faceCluster, srcDir); !s) return finish(s, j, a.jsonPath);
  if (pair)
    if (cbd::Status s = cbd::writeLayout(tr.layout, tr.faceCluster, a.out + "/target"); !s) return finish(s, j, a.jsonPath);
  j["timing_s"]["total"] = elapsed(t0);
  std::printf("source  %s: %d vertices, %d faces, genus %d, %zu anchors\n", a.mesh.c_str(), sourceReport.vertices,
              sourceReport.faces, sourceReport.genus, sourceAnchors.size());
  std::printf("layout  %zu edges (%d across Voronoi cuts, %d triangulating), %zu patches, %d multiple linkages\n",
              r.layout.edges.size(), r.cutPaths - r.removedPaths, r.triangulationPaths, r.layout.patches.size(),
              r.layout.multipleLinkages());
  std::printf("time    voronoi %.3f s, source layout %.3f s", r.voronoiSeconds, r.layoutSeconds);
  if (pair) std::printf(", target layout %.3f s", tr.voronoiSeconds + tr.layoutSeconds);
  std::printf("\n");
  if (pair) {
    std::printf("target  %s: same layout traced (%d paths inside the two clusters, %d in the whole region)\n",
                a.target.c_str(), tr.embeddedInClusters, tr.embeddedInRegion);
    std::printf("wrote   %s/{source,target}/{layout,paths,clusters}.ply\n", a.out.c_str());
  } else {
    std::printf("wrote   %s/{layout,paths,clusters}.ply\n", a.out.c_str());
  }
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
  const std::vector<int> vs = cbd::farthestPointSampling(im, a.count, a.seed);
  std::vector<cbd::Anchor> anchors;
  for (size_t k = 0; k < vs.size(); ++k) {
    cbd::Anchor an;
    an.name = "a" + std::to_string(k + 1);
    an.position = im.positions[vs[k]];
    anchors.push_back(an);
  }
  const cbd::Status s = cbd::writePickedPoints(a.out, anchors, std::filesystem::path(a.mesh).filename().string());
  if (s) std::printf("wrote %zu anchors to %s\n", anchors.size(), a.out.c_str());
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

  LayoutArgs layout;
  CLI::App* cmdLayout = app.add_subcommand(
      "layout",
      "Build the base domain on the source (Sec. 5.1): Voronoi clusters of the anchors, a path across "
      "every cut, triangulation of the rest; with --target, trace the same layout on the target (Sec. 5.2). "
      "Writes layout.ply (faces coloured by patch), paths.ply and clusters.ply per surface.");
  cmdLayout->add_option("--source,-s", layout.mesh, "mesh (.ply, .off, .obj, .stl)")->required();
  cmdLayout->add_option("--source-anchors", layout.anchors, "anchors (.pp, vertex list or name x y z)")->required();
  auto* tgtOpt = cmdLayout->add_option("--target,-t", layout.target,
                                       "target mesh: also trace the same layout on it (Procedure 1); outputs go "
                                       "to OUT/source and OUT/target, corresponding patches in the same colour");
  cmdLayout->add_option("--target-anchors", layout.targetAnchors, "target anchors, matched to the source's by name")
      ->needs(tgtOpt);
  tgtOpt->needs("--target-anchors");
  cmdLayout->add_option("--out,-o", layout.out, "output folder (created when missing)")->required();
  cmdLayout->add_option("--method", layout.method,
                        "voronoi: the Voronoi-cue method (Kwok et al. 2012); greedy: the greedy shortest-path "
                        "baseline (Kraevoy & Sheffer 2004), which needs --target")
      ->capture_default_str()
      ->check(CLI::IsMember({"voronoi", "greedy"}));
  cmdLayout->add_option("--min-edge-nodes", layout.minEdgeNodes, "b: minimum edge nodes per edge")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  cmdLayout->add_flag("--single-edge-node", layout.singleEdgeNode,
                      "one edge node per edge, no adaptivity (the paper's E1 setting)");
  cmdLayout->add_option("--snap-tolerance", layout.snapTolerance, "largest anchor snap distance (fraction of bbox diagonal)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  cmdLayout->add_option("--json", layout.jsonPath, "also write a JSON report to this file ('-' for stdout)");

  SampleArgs sample;
  CLI::App* cmdSample = app.add_subcommand(
      "sample-anchors", "Write N anchors spread by geodesic farthest-point sampling to a MeshLab .pp file.");
  cmdSample->add_option("--mesh,-m", sample.mesh, "mesh (.ply, .off, .obj, .stl)")->required();
  cmdSample->add_option("--count,-n", sample.count, "number of anchors")->required()->check(CLI::Range(1, 100000));
  cmdSample->add_option("--seed", sample.seed, "index of the first vertex")->capture_default_str();
  cmdSample->add_option("--out,-o", sample.out, "output .pp file")->required();

  CLI::App* cmdCodes = app.add_subcommand(
      "exit-codes", "List every exit code with its status name (as in the JSON \"status\") and meaning.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "cbd: error: invalid_argument: " << e.what() << " (see cbd --help)\n";
    return cbd::exitCode(cbd::ErrorCode::InvalidArgument);
  }

  try {
    if (*cmdCheck) return runCheck(check);
    if (*cmdLayout) return runLayout(layout);
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
