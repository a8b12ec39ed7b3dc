#include "cbd/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace cbd {
namespace {
double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

const char* layoutMethodName(LayoutMethod m) { return m == LayoutMethod::Voronoi ? "voronoi" : "greedy"; }

std::string addedAnchorName(int k) { return "added" + std::to_string(k + 1); }

Status validate(const CrossParameterizationOptions& o) {
  auto outside = [](const char* what, IntRange r, int v) {
    return Status::error(ErrorCode::InvalidArgument, std::string(what) + " must be in " + std::to_string(r.lo) + ".." +
                                                         std::to_string(r.hi) + ", got " + std::to_string(v));
  };
  if (!kMinEdgeNodesRange.contains(o.edgeNodes.minEdgeNodes))
    return outside("the minimum number of edge nodes", kMinEdgeNodesRange, o.edgeNodes.minEdgeNodes);
  if (!kStraightenRoundsRange.contains(o.straightening.rounds))
    return outside("the rounds of path straightening", kStraightenRoundsRange, o.straightening.rounds);
  if (!kSmoothingIterationsRange.contains(o.smoothing.iterations))
    return outside("the smoothing iterations", kSmoothingIterationsRange, o.smoothing.iterations);
  if (!(o.reverseDetour >= 0) || !(o.detourWarning >= 0))
    return Status::error(ErrorCode::InvalidArgument, "the detour thresholds must be numbers >= 0 (0: off)");
  return Status::success();
}

namespace {

/// The Voronoi method with `from` as the surface whose diagram gives the layout. `ontoIsFrom`:
/// `onto` is `from` itself with the same anchors, and gets the same layout.
LayoutPair voronoiLayouts(const IndexedMesh& from, const std::vector<int>& fa, const IndexedMesh& onto,
                          const std::vector<int>& ta, int euler, const CrossParameterizationOptions& options,
                          const Progress& progress, bool ontoIsFrom = false) {
  LayoutPair p;
  p.method = LayoutMethod::Voronoi;
  SourceLayoutOptions so;
  so.edgeNodes = options.edgeNodes;
  so.anchorNames = options.anchorNames;
  TargetLayoutOptions to;
  to.edgeNodes = options.edgeNodes;
  to.anchorNames = options.anchorNames;
  // Where the source layout gets stuck, or the target's at a handle, an anchor pair is added
  // there (anchor_pairs.h, target_layout.h) and both layouts are built again with it, up to the
  // cap.
  const int genus = (2 - euler) / 2;
  const int maxPairs = options.maxAnchorPairs >= 0 ? options.maxAnchorPairs : 4 * genus + 2;
  std::vector<int> sourceAnchors = fa, targetAnchors = ta;
  auto addPair = [&](int sourceVertex, int targetVertex) {
    p.addedAnchors.push_back({sourceVertex, targetVertex});
    sourceAnchors.push_back(sourceVertex);
    targetAnchors.push_back(targetVertex);
    if (!options.anchorNames.empty()) {
      so.anchorNames.push_back(addedAnchorName(static_cast<int>(p.addedAnchors.size()) - 1));
      to.anchorNames = so.anchorNames;
    }
  };
  auto full = [&] { return static_cast<int>(p.addedAnchors.size()) >= maxPairs; };
  // The last pair added where the target layout got stuck at a handle, and the candidates for its
  // target vertex (target_layout.h), best placed first.
  size_t handlePair = 0;
  std::vector<int> handleCandidates;
  // The target layout from the source's, with these target anchors, its times counted. On a
  // surface with handles Procedure 1's order may complete a layout whose paths wind round a
  // handle; the source's order then detours less (target_layout.h). Genus 0 keeps Procedure 1.
  auto traceTarget = [&](const std::vector<int>& anchors, const Progress& part) {
    TargetLayoutOptions tracing = to;
    if (euler < 2) tracing.order = TargetLayoutOptions::Order::Shorter;
    TargetLayoutResult t = buildTargetLayout(p.sourceStats.layout, onto, anchors, tracing, part);
    p.times.voronoi += t.voronoiSeconds;
    p.times.targetLayout += t.layoutSeconds;
    return t;
  };
  auto failedAfterPairs = [&](const Status& status) {
    p.status = status;
    if (!p.addedAnchors.empty())
      p.status.message += " (after adding " + std::to_string(p.addedAnchors.size()) + " anchor pairs" +
                          (full() ? ", the most allowed)" : ")");
    return p;
  };
  for (;;) {
    for (;;) {
      p.sourceStats = buildSourceLayout(from, sourceAnchors, so, progress.part(0.0, ontoIsFrom ? 1.0 : 0.5));
      p.times.voronoi += p.sourceStats.voronoiSeconds;
      p.times.sourceLayout += p.sourceStats.layoutSeconds;
      if (p.sourceStats.status || !p.sourceStats.stuck || full()) break;
      AnchorPairResult pair;
      if (ontoIsFrom) {
        pair.sourceVertex = pair.targetVertex = p.sourceStats.stuckVertex;
        if (pair.sourceVertex < 0) break;
      } else {
        AnchorPairOptions ao;
        ao.target = to;
        const auto t0 = std::chrono::steady_clock::now();
        pair = placeAnchorPair(p.sourceStats, onto, targetAnchors, ao, progress.quiet());
        p.times.targetLayout += seconds(t0);
        if (!pair.status) return p.status = pair.status, p;  // cancelled, or no pair to add
      }
      addPair(pair.sourceVertex, pair.targetVertex);
    }
    if (!p.sourceStats.status) return failedAfterPairs(p.sourceStats.status);
    if (const LayoutCheck c = validateLayout(p.sourceStats.layout, euler); !c.status) return p.status = c.status, p;
    if (ontoIsFrom) {
      p.source = std::move(p.sourceStats.layout);
      p.target = p.source;
      p.sameSurface = true;
      return p;
    }
    p.targetStats = traceTarget(targetAnchors, progress.part(0.5, 1.0));
    if (p.targetStats.status) break;
    // Stuck where a source path runs round a handle no target path passes the same way: an
    // anchor pair at that handle, placed alike in the two partial layouts' matching regions,
    // gives the paths a corner there (as for a stuck source layout), and both are built again.
    const TargetLayoutResult& t = p.targetStats;
    if (t.status.code != ErrorCode::LayoutFailed || t.handleSourceVertex < 0 || t.handleTargetVertices.empty() || full())
      return failedAfterPairs(t.status);
    handlePair = p.addedAnchors.size();
    handleCandidates = t.handleTargetVertices;
    addPair(t.handleSourceVertex, handleCandidates[0]);
  }
  p.detour = lengthDetour(p.sourceStats.layout, p.targetStats.layout);
  // The pair's target vertex placed alike relative to the region's sides can sit on the wrong
  // side of a thin part, and the paths then wind round it: while the layout detours more than
  // `detourWarning`, the runners-up are tried in turn (the source layout stays as it is) and the
  // layout that detours least is kept.
  for (size_t k = 1; k < handleCandidates.size() && p.detour > options.detourWarning; ++k) {
    std::vector<int> anchors = targetAnchors;
    anchors[ta.size() + handlePair] = handleCandidates[k];
    TargetLayoutResult other = traceTarget(anchors, progress.quiet());
    if (other.status.code == ErrorCode::Cancelled) return p.status = other.status, p;
    if (!other.status) continue;
    if (const double d = lengthDetour(p.sourceStats.layout, other.layout); d < p.detour) {
      p.detour = d;
      p.targetStats = std::move(other);
      targetAnchors = anchors;
      p.addedAnchors[handlePair].second = handleCandidates[k];
    }
  }
  p.source = std::move(p.sourceStats.layout);
  p.target = std::move(p.targetStats.layout);
  return p;
}

}  // namespace

LayoutPair buildLayouts(const IndexedMesh& source, const std::vector<int>& sa, const IndexedMesh& target,
                        const std::vector<int>& ta, int euler, const CrossParameterizationOptions& options,
                        const Progress& progress) {
  LayoutPair p;
  if (Status s = validate(options); !s) return p.status = s, p;
  p.method = options.method;
  if (options.method == LayoutMethod::Greedy) {
    GreedyLayoutOptions g;
    g.edgeNodes = options.edgeNodes;
    g.anchorNames = options.anchorNames;
    g.flipPaths = options.greedyFlipPaths;
    p.greedyStats = buildGreedyLayout(source, sa, target, ta, g, progress);
    p.times.sourceLayout = p.greedyStats.candidateSeconds + p.greedyStats.layoutSeconds;
    if (!p.greedyStats.status) return p.status = p.greedyStats.status, p;
    p.source = std::move(p.greedyStats.source);
    p.target = std::move(p.greedyStats.target);
    p.detour = lengthDetour(p.source, p.target);
    if (const LayoutCheck c = validateLayout(p.source, euler); !c.status) return p.status = c.status, p;
  } else {
    // One surface with the same anchors on both sides: one diagram, one layout for both.
    const bool same = source.positions == target.positions && source.faces == target.faces && sa == ta;
    p = voronoiLayouts(source, sa, target, ta, euler, options, progress, same);
    // A target layout whose paths are far longer than their source counterparts has detoured
    // around anchors (a twist): the target's own Voronoi diagram may be the better cue.
    const bool retry = !same && options.reverseDetour > 0 && p.status.code != ErrorCode::Cancelled &&
                       (!p.status || p.detour > options.reverseDetour);
    if (retry) {
      const StageTimes first = p.times;
      LayoutPair q = voronoiLayouts(target, ta, source, sa, euler, options, progress);
      const StageTimes second = q.times;
      // Both detours measured source -> target (the measure is not quite symmetric: the median
      // of an even count of ratios), so that the one kept is the lower as reported.
      const double reverse = q.status ? lengthDetour(q.target, q.source) : 0.0;
      if (q.status.code == ErrorCode::Cancelled) return q;
      if (q.status && (!p.status || reverse < p.detour)) {
        const double forwardDetour = p.status ? p.detour : 0.0;
        p = std::move(q);
        std::swap(p.source, p.target);
        for (auto& [a, b] : p.addedAnchors) std::swap(a, b);
        p.reversed = true;
        p.reverseDetour = forwardDetour;
        p.detour = reverse;
      } else {
        p.reverseDetour = reverse;
      }
      p.triedReverse = true;
      p.times.voronoi = first.voronoi + second.voronoi;
      p.times.sourceLayout = first.sourceLayout + second.sourceLayout;
      p.times.targetLayout = first.targetLayout + second.targetLayout;
    }
    if (!p.status) return p;
    if (options.flipPaths && !p.sameSurface) {
      const PathFlippingResult f = flipLayoutPaths(p.source, p.target, options.edgeNodes);
      p.times.targetLayout += f.seconds;
      if (!f.status) return p.status = f.status, p;
      p.flips = f.flips;
      // Both layouts changed: check both.
      if (f.flips > 0)
        if (const LayoutCheck c = validateLayout(p.reversed ? p.target : p.source, euler); !c.status)
          return p.status = c.status, p;
    }
  }
  // Check the layout not checked yet: the Voronoi method checked the one its diagram gave
  // before tracing the other from it (on a mesh paired with itself both are that one), the
  // greedy baseline the source's; both builders end with checkIsomorphic.
  const Layout* unchecked = &p.target;
  if (p.method == LayoutMethod::Voronoi) unchecked = p.sameSurface ? nullptr : p.reversed ? &p.source : &p.target;
  if (unchecked)
    if (const LayoutCheck c = validateLayout(*unchecked, euler); !c.status) return p.status = c.status, p;
  if (!p.addedAnchors.empty()) {
    std::string list;
    for (size_t k = 0; k < p.addedAnchors.size(); ++k)
      list += (k ? ", " : "") + addedAnchorName(static_cast<int>(k)) + " at vertex " +
              std::to_string(p.addedAnchors[k].first) +
              (p.sameSurface ? std::string() : " / " + std::to_string(p.addedAnchors[k].second));
    p.warnings.push_back(std::to_string(p.addedAnchors.size()) + (p.sameSurface ? " anchor" : " anchor pair") +
                         (p.addedAnchors.size() == 1 ? " was" : "s were") +
                         " added at handles smaller than the anchor spacing (where no path could split a region, or no "
                         "target path passed a handle as the source's did): " +
                         list + (p.sameSurface ? "" : " (source / target)") +
                         "; the untangling may move their images (the experimental optimization keeps them): give "
                         "anchors there to choose their places");
  }
  if (options.detourWarning > 0 && p.detour > options.detourWarning && !p.sameSurface) {
    char d[32];
    std::snprintf(d, sizeof d, "%.2f", p.detour);
    p.warnings.push_back(std::string("the target layout's paths detour ") + d +
                         " (their lengths against the source's; matching anchors on real pairs give 1.2-1.7" +
                         (p.triedReverse ? ", and both surfaces' Voronoi diagrams were tried" : "") +
                         "): check that the anchors correspond in shape, not only in name (left and right "
                         "swapped?); the map may fold over and its untangling take minutes");
  }
  return p;
}

CrossParameterizationResult crossParameterize(const IndexedMesh& source, const std::vector<int>& sa,
                                              const IndexedMesh& target, const std::vector<int>& ta, int euler,
                                              const CrossParameterizationOptions& options,
                                              const Progress& progress) {
  CrossParameterizationResult r;
  const auto t0 = std::chrono::steady_clock::now();
  if (Status s = validate(options); !s) return r.status = s, r;
  // Shares of the progress bar, by the stages' usual share of the time.
  const Progress layoutsPart = progress.part(0.0, 0.2), straightenPart = progress.part(0.2, 0.3),
                 patchesPart = progress.part(0.3, 0.4), mapPart = progress.part(0.4, 0.95);
  r.layouts = buildLayouts(source, sa, target, ta, euler, options, layoutsPart);
  r.times = r.layouts.times;
  if (!r.layouts.status) return r.status = r.layouts.status, r;
  auto t1 = std::chrono::steady_clock::now();
  if (options.straightening.rounds > 0) {
    // Both surfaces or neither: if either result fails its checks, both layouts stay as traced
    // (corresponding quadrilaterals must get corresponding diagonals).
    auto straighten = [&](const Layout& L, PathStraighteningResult& out, const Progress& p) {
      Layout copy = L;
      out = straightenPaths(copy, options.straightening, p);
      if (out.status)
        if (const LayoutCheck c = validateLayout(copy, euler); !c.status) out.status = c.status;
      return copy;
    };
    // The surfaces are independent: the target on a second thread.
    Layout t;
    std::thread other([&] { t = straighten(r.layouts.target, r.straightenTarget, straightenPart.quiet()); });
    Layout s = straighten(r.layouts.source, r.straightenSource, straightenPart);
    other.join();
    if (progress.cancelled())
      return r.status = Status::error(ErrorCode::Cancelled, "cancelled while straightening the paths"), r;
    if (r.straightenSource.status && r.straightenTarget.status) {
      r.layouts.source = std::move(s);
      r.layouts.target = std::move(t);
    } else {
      r.straightenFailed = true;
    }
    if (!checkIsomorphic(r.layouts.source, r.layouts.target))
      return r.status = Status::error(ErrorCode::InternalError, "the straightened layouts are not isomorphic"), r;
    r.times.straighten = seconds(t1);
    t1 = std::chrono::steady_clock::now();
  }
  for (Layout* L : {&r.layouts.source, &r.layouts.target}) splitCollinearFaces(*L);
  r.sourceParam = parameterizePatches(r.layouts.source, options.parameterization, patchesPart.part(0.0, 0.5));
  if (!r.sourceParam.status) return r.status = r.sourceParam.status, r;
  r.targetParam = parameterizePatches(r.layouts.target, options.parameterization, patchesPart.part(0.5, 1.0));
  if (!r.targetParam.status) return r.status = r.targetParam.status, r;
  r.map = composeCrossMap(r.layouts.source, r.sourceParam, r.layouts.target, r.targetParam);
  if (!r.map.status) return r.status = r.map.status, r;
  if (options.smoothing.iterations > 0) {
    r.smoothing = smoothCrossMap(source, r.layouts.source, r.sourceParam, target, r.layouts.target, r.targetParam,
                                 r.map, options.smoothing);
    if (!r.smoothing.status) return r.status = r.smoothing.status, r;
  }
  r.times.parameterization = seconds(t1);
  if (options.untangle) {
    const auto t2 = std::chrono::steady_clock::now();
    r.composedMetrics = computeDistortion(source, r.map.sourceImage, target, r.map.sourceToTarget);
    r.times.distortion = seconds(t2);
    if (!r.composedMetrics.status) return r.status = r.composedMetrics.status, r;
  }
  t1 = std::chrono::steady_clock::now();
  if (options.untangle && options.mapStage == MapStage::Optimize) {
    const BaseDomain domain(r.layouts.source);
    const SurfaceInDomain sourceInD(r.layouts.source, r.sourceParam, domain);
    const SurfaceInDomain targetInD(r.layouts.target, r.targetParam, domain);
    CrossMap optimized = optimizeCrossMap(source, target, sourceInD, targetInD, domain, options.optimization,
                                          r.optimization, mapPart);
    r.times.untangle = seconds(t1);
    if (!r.optimization.status) return r.status = r.optimization.status, r;
    r.map = std::move(optimized);
  } else if (options.untangle) {
    std::vector<char> fixedS(source.vertexCount(), 0), fixedT(target.vertexCount(), 0);
    for (int v : sa) fixedS[v] = 1;
    for (int v : ta) fixedT[v] = 1;
    // The two directions are independent: one on a second thread.
    std::thread inverse([&] {
      r.untangleTarget = untangleCrossMap(target, source, fixedT, r.map.targetToSource, r.map.targetImage,
                                          options.untangling, mapPart.quiet());
    });
    r.untangleSource =
        untangleCrossMap(source, target, fixedS, r.map.sourceToTarget, r.map.sourceImage, options.untangling, mapPart);
    inverse.join();
    if (progress.cancelled())
      return r.status = Status::error(ErrorCode::Cancelled, "cancelled while removing flipped triangles"), r;
    r.times.untangle = seconds(t1);
  }
  t1 = std::chrono::steady_clock::now();
  if (!progress.report(0.95, "measuring the distortion"))
    return r.status = Status::error(ErrorCode::Cancelled, "cancelled before measuring the distortion"), r;
  r.metrics = computeDistortion(source, r.map.sourceImage, target, r.map.sourceToTarget);
  r.times.distortion += seconds(t1);
  if (!r.metrics.status) return r.status = r.metrics.status, r;
  if (!options.untangle) r.composedMetrics = r.metrics;
  r.times.total = seconds(t0);
  return r;
}

}  // namespace cbd
