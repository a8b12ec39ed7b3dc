#include "cbd/report.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "cbd/layout_io.h"
#include "cbd/map_io.h"

namespace cbd {
namespace {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
  va_list args, again;
  va_start(args, fmt);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, fmt, args);
  va_end(args);
  std::string s(static_cast<size_t>(std::max(n, 0)) + 1, '\0');
  std::vsnprintf(s.data(), s.size(), fmt, again);
  va_end(again);
  s.resize(static_cast<size_t>(std::max(n, 0)));
  return s;
}

Json pairInputJson(const InputReport& r, Json& j) {
  j["source"] = toJson(r.source);
  j["target"] = toJson(r.target);
  if (r.status && r.anchors.size() > 0) j["source"]["anchors"] = j["target"]["anchors"] = r.anchors.size();
  return j;
}

const char* plural(int n) { return n == 1 ? "" : "s"; }

/// `MapOptimizationStop` as the JSON report names it and as the log says it.
struct StopText {
  const char* name;
  const char* words;
};
StopText optimizationStopText(MapOptimizationStop s) {
  switch (s) {
    case MapOptimizationStop::Tolerance: return {"tolerance", "on the tolerance"};
    case MapOptimizationStop::NoDescent: return {"no_descent", "for want of a descent step"};
    case MapOptimizationStop::MaxIterations: return {"max_iterations", "at the iteration cap"};
  }
  return {"unknown", "for an unknown reason"};
}

}  // namespace

std::string fixed(double value, int digits) { return format("%.*f", digits, value); }

Json toJson(const MeshReport& m) {
  return Json{{"vertices", m.vertices},
              {"faces", m.faces},
              {"genus", m.genus},
              {"unreferenced_vertices", m.unreferencedVertices},
              {"bbox_diagonal", m.bboxDiagonal},
              {"enclosed_volume", m.enclosedVolume},
              {"warnings", m.warnings}};
}

namespace {
/// The anchor pairs the layouts added: name and vertex on each surface (one surface: "vertex").
Json addedAnchorsJson(const LayoutPair& p) {
  Json list = Json::array();
  for (size_t k = 0; k < p.addedAnchors.size(); ++k) {
    Json a = {{"name", addedAnchorName(static_cast<int>(k))}};
    if (p.sameSurface) {
      a["vertex"] = p.addedAnchors[k].first;
    } else {
      a["source_vertex"] = p.addedAnchors[k].first;
      a["target_vertex"] = p.addedAnchors[k].second;
    }
    list.push_back(a);
  }
  return list;
}
}  // namespace

Json toJson(const LayoutPair& p) {
  Json l = {{"edges", p.source.edges.size()},
            {"patches", p.source.patches.size()},
            {"multi_linkages", p.source.multipleLinkages()},
            {"detour", p.detour},
            {"warnings", p.warnings}};
  if (p.method == LayoutMethod::Voronoi) {
    l["added_anchors"] = addedAnchorsJson(p);
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
                   {"rejected_paths", p.targetStats.rejectedPaths},
                   {"past_closed_corridors", p.targetStats.pastClosedCorridors},
                   {"order", p.targetStats.inSourceOrder ? "source" : "procedure1"}};
    if (!p.targetStats.procedure1Failure.empty()) l["target"]["procedure1_failure"] = p.targetStats.procedure1Failure;
    if (p.targetStats.procedure1Detour > 0) l["target"]["procedure1_detour"] = p.targetStats.procedure1Detour;
  } else {
    const auto& g = p.greedyStats;
    l["greedy"] = {{"candidates", g.candidates}, {"tried", g.tried},         {"accepted", g.accepted},
                   {"rejected", g.rejected},     {"completion_paths", g.completionPaths},
                   {"completion_rejected", g.completionRejected}, {"flips", g.flips}};
  }
  return l;
}

Json toJson(const StageTimes& t) {
  return {{"voronoi", t.voronoi},         {"source_layout", t.sourceLayout},
          {"target_layout", t.targetLayout}, {"straighten", t.straighten},
          {"parameterization", t.parameterization},
          {"untangle", t.untangle},       {"distortion", t.distortion},   {"total", t.total}};
}

Json toJson(const DistortionMetrics& m) {
  return {{"e_ang", m.eAng},         {"e_ang_deg", m.eAngDegrees}, {"e_l2", m.eL2},
          {"e_l2_inverse", m.eL2Inverse}, {"flipped", m.flipped},      {"degenerate", m.degenerate}};
}

Json checkJson(const InputReport& r) {
  Json j;
  pairInputJson(r, j);
  if (!r.status) return j;
  Json list = Json::array();
  for (int k = 0; k < r.anchors.size(); ++k) {
    const auto& s = r.anchors.source[k];
    const auto& t = r.anchors.target[k];
    list.push_back({{"name", r.anchors.names[k]},
                    {"source_vertex", s.vertex},
                    {"target_vertex", t.vertex},
                    {"source_snap", s.snapDistance},
                    {"target_snap", t.snapDistance}});
  }
  j["anchors"] = list;
  return j;
}

Json layoutJobJson(const LayoutJob& job, const LayoutJobResult& r) {
  Json j;
  if (!job.paired()) {
    j["source"] = toJson(r.single.report);
    if (r.single.status) j["source"]["anchors"] = r.single.anchors.size();
    if (!r.computed) return j;
    const SourceLayoutResult& l = r.singleLayout;
    j["timing_s"] = {{"voronoi", r.times.voronoi}, {"source_layout", r.times.sourceLayout}};
    if (r.status) {
      j["timing_s"]["total"] = r.times.total;
      j["layout"] = {{"edges", l.layout.edges.size()},         {"patches", l.layout.patches.size()},
                     {"multi_linkages", l.layout.multipleLinkages()}, {"cut_paths", l.cutPaths},
                     {"triangulation_paths", l.triangulationPaths},   {"removed_paths", l.removedPaths},
                     {"rejected_paths", l.rejectedPaths},
                     {"added_anchors", addedAnchorsJson(r.layouts)},
                     {"warnings", r.layouts.warnings}};
    }
    return j;
  }
  j["method"] = layoutMethodName(job.pipeline.method);
  pairInputJson(r.input.report, j);
  if (!r.computed) return j;
  j["timing_s"] = toJson(r.times);
  if (r.status) j["layout"] = toJson(r.layouts);
  return j;
}

Json mapJobJson(const MapJob& job, const MapJobResult& out) {
  Json j;
  j["method"] = layoutMethodName(job.pipeline.method);
  pairInputJson(out.input.report, j);
  if (!out.computed) return j;
  const CrossParameterizationResult& r = out.result;
  const CrossParameterizationOptions& o = job.pipeline;
  j["timing_s"] = toJson(r.times);
  if (!r.status) return j;
  j["layout"] = toJson(r.layouts);
  if (o.straightening.rounds > 0) {
    auto side = [](const PathStraighteningResult& s) {
      return Json{{"straightened", s.straightened}, {"skipped", s.skipped}, {"splits", s.splits},
                  {"length_before", s.lengthBefore}, {"length_after", s.lengthAfter}};
    };
    j["straighten"] = {{"rounds", o.straightening.rounds}, {"source", side(r.straightenSource)},
                       {"target", side(r.straightenTarget)}, {"failed", r.straightenFailed}};
    for (const auto* s : {&r.straightenSource, &r.straightenTarget})
      if (!s->status) j["straighten"]["error"] = s->status.message;
  }
  if (o.smoothing.iterations > 0)
    j["smoothing"] = {{"iterations", o.smoothing.iterations}, {"moves", r.smoothing.moves},
                      {"rejected", r.smoothing.rejected},     {"flipped_before", r.smoothing.flippedBefore},
                      {"flipped_after", r.smoothing.flippedAfter}};
  if (o.untangle && o.mapStage == MapStage::Optimize) {
    const auto& p = r.optimization;
    j["optimize"] = {{"iterations", p.iterations},      {"stop", optimizationStopText(p.stop).name},
                     {"bounded_steps", p.boundedSteps}, {"converged", p.converged},
                     {"energy_before", p.energyBefore}, {"energy_after", p.energyAfter},
                     {"injective", p.injective}};
  } else if (o.untangle) {
    const auto &u = r.untangleSource, &w = r.untangleTarget;
    j["untangle"] = {{"flipped_before", u.flippedBefore},         {"flipped_after", u.flippedAfter},
                     {"moved_vertices", u.movedVertices},         {"inverse_flipped_before", w.flippedBefore},
                     {"inverse_flipped_after", w.flippedAfter},   {"inverse_moved_vertices", w.movedVertices},
                     {"attempts", u.attempts},                    {"inverse_attempts", w.attempts}};
  }
  j["metrics"] = toJson(r.metrics);
  j["metrics"]["composed"] = toJson(r.composedMetrics);
  return j;
}

std::string meshLine(const char* role, const std::string& path, const MeshReport& m) {
  return format("%-7s %s: %d vertices, %d faces, genus %d", role, path.c_str(), m.vertices, m.faces, m.genus);
}

std::vector<std::string> checkLines(const InputFiles& files, const InputReport& r) {
  std::vector<std::string> lines;
  for (const auto& [role, path, mesh] : {std::tuple{"source", &files.sourceMesh, &r.source},
                                         std::tuple{"target", &files.targetMesh, &r.target}}) {
    lines.push_back(meshLine(role, *path, *mesh));
    for (const auto& w : mesh->warnings) lines.push_back("  warning: " + w);
  }
  double worstS = 0, worstT = 0;
  for (int k = 0; k < r.anchors.size(); ++k) {
    worstS = std::max(worstS, r.anchors.source[k].snapDistance);
    worstT = std::max(worstT, r.anchors.target[k].snapDistance);
  }
  lines.push_back(format("anchors %d pairs matched by name; largest snap distance %.3g%% (source), %.3g%% (target) "
                         "of the bbox diagonal",
                         r.anchors.size(), 100 * worstS, 100 * worstT));
  lines.push_back("ok: the pair can be processed");
  return lines;
}

std::vector<std::string> layoutLines(const LayoutPair& p) {
  std::vector<std::string> lines;
  if (p.method == LayoutMethod::Voronoi) {
    lines.push_back(format("layout  voronoi: %zu edges (%d across Voronoi cuts, %d triangulating), %zu patches, %d "
                           "multiple linkages",
                           p.source.edges.size(), p.sourceStats.cutPaths - p.sourceStats.removedPaths,
                           p.sourceStats.triangulationPaths, p.source.patches.size(), p.source.multipleLinkages()));
    if (!p.addedAnchors.empty())
      lines.push_back(format("        %zu anchor pair%s added where a handle is smaller than the anchor spacing",
                             p.addedAnchors.size(), plural(static_cast<int>(p.addedAnchors.size()))));
    if (p.sameSurface)
      lines.push_back("        target: the source itself (same vertices, faces and anchors): the same layout");
    else
      lines.push_back(format("        %s: %d paths inside the two clusters, %d in the whole region; detour %.2f",
                             p.reversed ? "traced on the source" : "target", p.targetStats.embeddedInClusters,
                             p.targetStats.embeddedInRegion, p.detour));
    if (p.targetStats.inSourceOrder && !p.targetStats.procedure1Failure.empty())
      lines.push_back("        traced in the source's order: Procedure 1's got stuck at " + p.targetStats.procedure1Failure);
    else if (p.targetStats.inSourceOrder && p.targetStats.procedure1Detour > 0)
      lines.push_back(format("        traced in the source's order: Procedure 1's paths detoured by %.2f",
                             p.targetStats.procedure1Detour));
    if (p.targetStats.pastClosedCorridors > 0)
      lines.push_back(format("        %d path%s found only with the corridors of refused ones closed (passing a "
                             "handle on another side than the shortest path)",
                             p.targetStats.pastClosedCorridors, plural(p.targetStats.pastClosedCorridors)));
    if (p.reversed)
      lines.push_back(format("        (the layout traced from the source's diagram detoured by %.2f: this one comes "
                             "from the target's Voronoi diagram)",
                             p.reverseDetour));
    if (p.flips > 0) lines.push_back(format("        path flipping: %d edges replaced on both surfaces", p.flips));
  } else {
    const auto& g = p.greedyStats;
    lines.push_back(format("layout  greedy: %zu edges, %zu patches; %d candidate pairs, %d traced, %d accepted, %d "
                           "rejected, %d completion paths (%d undone), %d flips",
                           p.source.edges.size(), p.source.patches.size(), g.candidates, g.tried, g.accepted,
                           g.rejected, g.completionPaths, g.completionRejected, g.flips));
  }
  return lines;
}

std::vector<std::string> mapLines(const CrossParameterizationResult& r, const CrossParameterizationOptions& o,
                                  const DistortionMetrics* inverse) {
  std::vector<std::string> lines;
  const int rounds = o.straightening.rounds;
  if (rounds > 0) {
    const auto &s = r.straightenSource, &t = r.straightenTarget;
    if (r.straightenFailed)
      lines.push_back(format("straighten failed (%s): both layouts kept as traced",
                             (!s.status ? s.status : t.status).message.c_str()));
    else
      lines.push_back(format("straighten %d round%s: %d / %d paths straightened (source / target), total length "
                             "%.4g -> %.4g / %.4g -> %.4g",
                             rounds, plural(rounds), s.straightened, t.straightened, s.lengthBefore, s.lengthAfter,
                             t.lengthBefore, t.lengthAfter));
  }
  const int sweeps = o.smoothing.iterations;
  if (sweeps > 0)
    lines.push_back(format("smooth  %d sweep%s over M_st: %d moves kept, %d rejected (a flip or outside the chart), "
                           "flipped %d -> %d",
                           sweeps, plural(sweeps), r.smoothing.moves, r.smoothing.rejected, r.smoothing.flippedBefore,
                           r.smoothing.flippedAfter));
  const DistortionMetrics& m = r.metrics;
  lines.push_back(format("map     E_ang %.4f (%.2f deg), E_L2 %.4f (inverse %.4f), %d flipped, %d degenerate triangles",
                         m.eAng, m.eAngDegrees, m.eL2, m.eL2Inverse, m.flipped, m.degenerate));
  if (o.untangle)
    lines.push_back(format("composed E_ang %.4f, E_L2 %.4f, %d flipped (the map before untangling)",
                           r.composedMetrics.eAng, r.composedMetrics.eL2, r.composedMetrics.flipped));
  if (o.untangle && o.mapStage == MapStage::Optimize) {
    const auto& p = r.optimization;
    std::string line = format("optimize %d iterations (stopped %s, %d cut short by the injectivity bound%s), "
                              "injective in the base domain",
                              p.iterations, optimizationStopText(p.stop).words, p.boundedSteps,
                              p.converged ? "" : ": not converged");
    if (inverse) line += format("; M_ts (its inverse): %d flipped", inverse->flipped);
    lines.push_back(line);
  } else if (o.untangle) {
    lines.push_back(format("untangle flipped triangles of M_st %d -> %d (%d vertices moved), of M_ts %d -> %d",
                           r.untangleSource.flippedBefore, r.untangleSource.flippedAfter,
                           r.untangleSource.movedVertices, r.untangleTarget.flippedBefore,
                           r.untangleTarget.flippedAfter));
  }
  return lines;
}

std::string timesLine(const StageTimes& t, bool withMap) {
  if (!withMap)
    return format("time    voronoi %.3f s, source layout %.3f s, target layout %.3f s, total %.3f s", t.voronoi,
                  t.sourceLayout, t.targetLayout, t.total);
  return format("time    voronoi %.3f s, source layout %.3f s, target layout %.3f s, straighten %.3f s, "
                "parameterization %.3f s, untangle %.3f s, total %.3f s",
                t.voronoi, t.sourceLayout, t.targetLayout, t.straighten, t.parameterization, t.untangle, t.total);
}

std::vector<std::string> layoutJobLines(const LayoutJob& job, const LayoutJobResult& r) {
  std::vector<std::string> lines;
  if (!job.paired()) {
    const MeshReport& m = r.single.report;
    const SourceLayoutResult& l = r.singleLayout;
    lines.push_back(format("source  %s: %d vertices, %d faces, genus %d, %zu anchors", job.files.sourceMesh.c_str(),
                           m.vertices, m.faces, m.genus, r.single.anchors.size()));
    lines.push_back(format("layout  %zu edges (%d across Voronoi cuts, %d triangulating), %zu patches, %d multiple "
                           "linkages",
                           l.layout.edges.size(), l.cutPaths - l.removedPaths, l.triangulationPaths,
                           l.layout.patches.size(), l.layout.multipleLinkages()));
    if (!r.layouts.addedAnchors.empty())
      lines.push_back(format("        %zu anchor%s added where a handle is smaller than the anchor spacing",
                             r.layouts.addedAnchors.size(), plural(static_cast<int>(r.layouts.addedAnchors.size()))));
    lines.push_back(format("time    voronoi %.3f s, layout %.3f s", r.times.voronoi, r.times.sourceLayout));
    lines.push_back(format("wrote   %s/{layout,paths,clusters}.ply", job.outDir.c_str()));
    return lines;
  }
  lines = layoutLines(r.layouts);
  lines.push_back(format("time    voronoi %.3f s, source layout %.3f s, target layout %.3f s", r.times.voronoi,
                         r.times.sourceLayout, r.times.targetLayout));
  lines.push_back(format("wrote   %s/{source,target}/{layout,paths%s}.ply", job.outDir.c_str(),
                         r.layouts.method == LayoutMethod::Voronoi ? ",clusters" : ""));
  return lines;
}

std::vector<std::string> mapJobLines(const MapJob& job, const MapJobResult& out) {
  const CrossParameterizationResult& r = out.result;
  std::vector<std::string> lines = layoutLines(r.layouts);
  for (std::string& l : mapLines(r, job.pipeline, &out.inverse)) lines.push_back(std::move(l));
  lines.push_back(timesLine(r.times, true));
  const char* dir = job.outDir.c_str();
  lines.push_back(format("wrote   %s/%s (source connectivity on the target; face quality = stretch), %s/%s,", dir,
                         kMstFile, dir, kMtsFile));
  lines.push_back(format("        %s/%s, %s/{%s,%s}/ layouts%s", dir, kCorrespondenceFile, dir, kSourceLayoutFolder,
                         kTargetLayoutFolder, job.morphFrames > 0 ? ", morph_*.ply" : ""));
  if (out.staleMorphFrames > 0)
    lines.push_back(format("removed %d morph frame%s after %s of an earlier, longer sequence", out.staleMorphFrames,
                           plural(out.staleMorphFrames), morphFileName(job.morphFrames - 1).c_str()));
  return lines;
}

std::vector<std::string> layoutWarnings(const LayoutPair& p) { return p.warnings; }

std::vector<std::string> inputWarnings(const InputReport& r) {
  std::vector<std::string> w = r.source.warnings;
  w.insert(w.end(), r.target.warnings.begin(), r.target.warnings.end());
  return w;
}

std::string summary(const DistortionMetrics& m, double seconds) {
  return format("E_ang %.4f (%.2f deg), E_L2 %.4f, %s, %.2f s", m.eAng, m.eAngDegrees, m.eL2,
                counted(m.flipped, "flipped triangle", "flipped triangles").c_str(), seconds);
}

}  // namespace cbd
