// cbd_bench: the comparison of the paper's Table 2 / Fig. 8 and the scaling runs.
// Every method runs on the same input in one invocation; each run is forked into a child
// process so that its peak resident memory (getrusage) is its own. See bench/README.md.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

#include "cbd/anchor_sampling.h"
#include "cbd/pipeline.h"
#include "cbd/validate_input.h"
#include "support/stress.h"

namespace fs = std::filesystem;
using namespace cbd;

namespace {

struct Method {
  std::string name;  // greedy | voronoi-E1 | voronoi-C, and "-traced" for the paths as traced
  CrossParameterizationOptions options;
};

/// The three methods with cbd's defaults (paths straightened, path_straightening.h), then the
/// greedy baseline and Voronoi C with their paths as traced: the paper's protocol, where
/// nothing but the map is post-processed.
std::vector<Method> methods() {
  Method g{"greedy", {}}, e1{"voronoi-E1", {}}, c{"voronoi-C", {}};
  g.options.method = LayoutMethod::Greedy;
  e1.options.edgeNodes.minEdgeNodes = 1;
  e1.options.edgeNodes.adaptive = false;
  Method gt{"greedy-traced", g.options}, ct{"voronoi-C-traced", c.options};
  gt.options.straightening.rounds = ct.options.straightening.rounds = 0;
  return {g, e1, c, gt, ct};
}

/// One run's numbers, as the child reports them.
struct Run {
  bool ok = false;
  std::string error;
  double eAng = 0, eAngDeg = 0, eL2 = 0, eL2Inv = 0;
  int flipped = 0, degenerate = 0, edges = 0, multi = 0;
  int flippedRaw = 0;  // before untangling (the composed map as it is)
  double eAngRaw = 0, eL2Raw = 0;  // the same
  double tVoronoi = 0, tSource = 0, tTarget = 0, tParam = 0, tLayout = 0, tTotal = 0, tStraighten = 0;
  double peakMB = 0;
};

/// Run `fn` in a child process; it writes one line of results to the pipe.
Run forked(const std::function<Run()>& fn) {
  int fd[2];
  if (pipe(fd) != 0) return Run{false, "pipe failed"};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    Run r;
    try {
      r = fn();
    } catch (const std::exception& e) {
      r.ok = false;
      r.error = e.what();
    }
    std::ostringstream o;
    o.precision(17);
    o << r.ok << ' ' << r.eAng << ' ' << r.eAngDeg << ' ' << r.eL2 << ' ' << r.eL2Inv << ' ' << r.flipped << ' '
      << r.degenerate << ' ' << r.edges << ' ' << r.multi << ' ' << r.tVoronoi << ' ' << r.tSource << ' ' << r.tTarget
      << ' ' << r.tParam << ' ' << r.tLayout << ' ' << r.tTotal << ' ' << r.flippedRaw << ' ' << r.eAngRaw << ' '
      << r.eL2Raw << ' ' << r.tStraighten << ' ' << r.error << '\n';
    const std::string s = o.str();
    (void)!write(fd[1], s.data(), s.size());
    _exit(0);
  }
  close(fd[1]);
  std::string out;
  char buf[4096];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof buf)) > 0) out.append(buf, static_cast<size_t>(n));
  close(fd[0]);
  int status = 0;
  struct rusage ru {};
  wait4(pid, &status, 0, &ru);
  Run r;
  std::istringstream in(out);
  if (!(in >> r.ok >> r.eAng >> r.eAngDeg >> r.eL2 >> r.eL2Inv >> r.flipped >> r.degenerate >> r.edges >> r.multi >>
        r.tVoronoi >> r.tSource >> r.tTarget >> r.tParam >> r.tLayout >> r.tTotal >> r.flippedRaw >> r.eAngRaw >>
        r.eL2Raw >> r.tStraighten)) {
    r.ok = false;
    r.error = "the run crashed (status " + std::to_string(status) + ")";
  } else {
    std::getline(in, r.error);
    if (!r.error.empty() && r.error[0] == ' ') r.error.erase(0, 1);
  }
  r.peakMB = ru.ru_maxrss / 1024.0;
  return r;
}

Run runPipeline(const IndexedMesh& s, const std::vector<int>& sa, const IndexedMesh& t, const std::vector<int>& ta,
                int euler, const CrossParameterizationOptions& o, bool layoutOnly) {
  Run r;
  const auto t0 = std::chrono::steady_clock::now();
  if (layoutOnly) {
    LayoutPair p = buildLayouts(s, sa, t, ta, euler, o);
    r.ok = p.status.ok();
    r.error = p.status.message;
    r.edges = static_cast<int>(p.source.edges.size());
    r.multi = p.source.multipleLinkages();
    r.tVoronoi = p.times.voronoi, r.tSource = p.times.sourceLayout, r.tTarget = p.times.targetLayout;
  } else {
    CrossParameterizationResult c = crossParameterize(s, sa, t, ta, euler, o);
    r.ok = c.status.ok();
    r.error = c.status.message;
    r.eAng = c.metrics.eAng, r.eAngDeg = c.metrics.eAngDegrees, r.eL2 = c.metrics.eL2, r.eL2Inv = c.metrics.eL2Inverse;
    r.flipped = c.metrics.flipped, r.degenerate = c.metrics.degenerate;
    r.flippedRaw = o.untangle ? c.untangleSource.flippedBefore : c.metrics.flipped;
    r.eAngRaw = c.composedMetrics.eAng, r.eL2Raw = c.composedMetrics.eL2;
    r.tStraighten = c.times.straighten;
    r.edges = static_cast<int>(c.layouts.source.edges.size());
    r.multi = c.layouts.source.multipleLinkages();
    r.tVoronoi = c.times.voronoi, r.tSource = c.times.sourceLayout, r.tTarget = c.times.targetLayout;
    r.tParam = c.times.parameterization;
  }
  r.tLayout = r.tVoronoi + r.tSource + r.tTarget;
  r.tTotal = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (char& ch : r.error)
    if (ch == '\n') ch = ' ';
  return r;
}

struct Pair {
  std::string name, source, target, sourceAnchors, targetAnchors;
};

std::string expand(std::string p, const fs::path& root) {
  const std::string shrec = "$SHREC";
  if (p.rfind(shrec, 0) == 0) p = (root.parent_path() / "shared/data/shrec07-fourleg").string() + p.substr(shrec.size());
  if (!p.empty() && p[0] != '/') p = (root / p).string();
  return p;
}

/// The pairs of `manifest` (lines "name source target source_anchors target_anchors", '#'
/// comments), their paths expanded against `root`. False when the manifest cannot be read.
bool readManifest(const fs::path& root, const std::string& manifest, std::vector<Pair>& pairs) {
  std::ifstream in(manifest);
  if (!in) {
    std::fprintf(stderr, "cbd_bench: cannot read manifest '%s'\n", manifest.c_str());
    return false;
  }
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Pair p;
    ls >> p.name >> p.source >> p.target >> p.sourceAnchors >> p.targetAnchors;
    p.source = expand(p.source, root), p.target = expand(p.target, root);
    p.sourceAnchors = expand(p.sourceAnchors, root), p.targetAnchors = expand(p.targetAnchors, root);
    pairs.push_back(p);
  }
  return true;
}

/// A pair loaded and validated, with its anchors as vertex indices.
struct LoadedPair {
  LoadedInput input;
  std::vector<int> sourceAnchors, targetAnchors;
};

/// Loads and validates `p` into `lp`: an empty string, or why the pair cannot run.
std::string loadPair(const Pair& p, LoadedPair& lp) {
  if (!fs::exists(p.source) || !fs::exists(p.target)) return "skipped: input not present";
  loadAndValidate({p.source, p.target, p.sourceAnchors, p.targetAnchors}, {}, lp.input);
  if (!lp.input.report.status) return "invalid input: " + lp.input.report.status.message;
  for (const auto& a : lp.input.report.anchors.source) lp.sourceAnchors.push_back(a.vertex);
  for (const auto& a : lp.input.report.anchors.target) lp.targetAnchors.push_back(a.vertex);
  return {};
}

/// The whole pipeline on a loaded pair with options `o`, in a child process of its own.
Run runPair(const LoadedPair& lp, const CrossParameterizationOptions& o) {
  return forked([&] {
    return runPipeline(lp.input.source, lp.sourceAnchors, lp.input.target, lp.targetAnchors,
                       lp.input.report.source.eulerCharacteristic, o, false);
  });
}

/// `orders` polish orders per default run of greedy and Voronoi C: the default (index order)
/// and orders - 1 seeded permutations (MapUntangleOptions::polishOrderSeed), each its own run,
/// written to OUTDIR/table_orders.csv.
int table(const fs::path& root, const std::string& manifest, const fs::path& out, int orders) {
  std::vector<Pair> pairs;
  if (!readManifest(root, manifest, pairs)) return 1;
  fs::create_directories(out);
  std::ofstream csv(out / "table.csv"), md(out / "table.md"), ocsv(out / "table_orders.csv");
  ocsv << "pair,method,order_seed,status,e_ang,e_l2,flipped,t_total,error\n";
  auto orderRow = [&](const std::string& pair, const std::string& method, int seed, const Run& r) {
    ocsv << pair << ',' << method << ',' << seed << ',' << (r.ok ? "ok" : "failed") << ',' << r.eAng << ',' << r.eL2
         << ',' << r.flipped << ',' << r.tTotal << ",\"" << r.error << "\"\n";
    ocsv.flush();
  };
  csv << "pair,source_vertices,target_vertices,anchors,method,status,e_ang,e_ang_deg,e_l2,e_l2_inverse,flipped,"
         "degenerate,edges,multi_linkages,t_voronoi,t_source_layout,t_target_layout,t_layout,t_parameterization,"
         "t_total,peak_mb,flipped_before_untangle,e_ang_composed,e_l2_composed,t_straighten,error\n";
  md << "| pair | V src / tgt | anchors | method | E_ang | E_L2 | flipped | layout s | total s | peak MB | note |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::string> speedups;
  for (const Pair& p : pairs) {
    LoadedPair lp;
    if (const std::string why = loadPair(p, lp); !why.empty()) {
      md << "| " << p.name << " | | | | | | | | | | " << why << " |\n";
      std::printf("%-24s %s\n", p.name.c_str(), why.c_str());
      continue;
    }
    const LoadedInput& li = lp.input;
    const std::vector<int>& sa = lp.sourceAnchors;
    std::map<std::string, Run> runs;
    for (const Method& m : methods()) {
      const Run r = runPair(lp, m.options);
      runs[m.name] = r;
      char row[1024];
      std::snprintf(row, sizeof row, "| %s | %d / %d | %zu | %s | %s | %s | %s | %.3f | %.3f | %.0f | %s |\n",
                    p.name.c_str(), li.report.source.vertices, li.report.target.vertices, sa.size(), m.name.c_str(),
                    r.ok ? std::to_string(r.eAng).substr(0, 5).c_str() : "-",
                    r.ok ? std::to_string(r.eL2).substr(0, 5).c_str() : "-",
                    r.ok ? std::to_string(r.flipped).c_str() : "-", r.tLayout, r.tTotal, r.peakMB,
                    r.ok ? "" : ("failed: " + r.error).substr(0, 160).c_str());
      md << row;
      csv << p.name << ',' << li.report.source.vertices << ',' << li.report.target.vertices << ',' << sa.size() << ','
          << m.name << ',' << (r.ok ? "ok" : "failed") << ',' << r.eAng << ',' << r.eAngDeg << ',' << r.eL2 << ','
          << r.eL2Inv << ',' << r.flipped << ',' << r.degenerate << ',' << r.edges << ',' << r.multi << ','
          << r.tVoronoi << ',' << r.tSource << ',' << r.tTarget << ',' << r.tLayout << ',' << r.tParam << ','
          << r.tTotal << ',' << r.peakMB << ',' << r.flippedRaw << ',' << r.eAngRaw << ',' << r.eL2Raw << ','
          << r.tStraighten << ",\"" << r.error << "\"\n";
      std::printf("%-22s %-16s %s E_ang %.3f E_L2 %.3f flipped %d (composed: %.3f %.3f %d) layout %.3fs total %.3fs "
                  "peak %.0f MB %s\n",
                  p.name.c_str(), m.name.c_str(), r.ok ? "ok    " : "FAILED", r.eAng, r.eL2, r.flipped, r.eAngRaw, r.eL2Raw,
                  r.flippedRaw, r.tLayout, r.tTotal, r.peakMB, r.ok ? "" : r.error.c_str());
      std::fflush(stdout);
    }
    // The same runs of the two methods compared with other polish orders: how far the end point
    // of the polish moves with the order alone, against the difference between the methods.
    for (const Method& m : methods()) {
      if (m.name != "greedy" && m.name != "voronoi-C") continue;
      orderRow(p.name, m.name, 0, runs[m.name]);
      for (int seed = 1; seed < orders; ++seed) {
        CrossParameterizationOptions o = m.options;
        o.untangling.polishOrderSeed = static_cast<std::uint64_t>(seed);
        const Run r = runPair(lp, o);
        orderRow(p.name, m.name, seed, r);
        std::printf("%-22s %-16s polish order %d: %s E_ang %.3f E_L2 %.3f flipped %d total %.3fs %s\n", p.name.c_str(),
                    m.name.c_str(), seed, r.ok ? "ok    " : "FAILED", r.eAng, r.eL2, r.flipped, r.tTotal,
                    r.ok ? "" : r.error.c_str());
        std::fflush(stdout);
      }
    }
    const Run &g = runs["greedy"], &c = runs["voronoi-C"];
    if (g.ok && c.ok && c.tLayout > 0) {
      char s[256];
      std::snprintf(s, sizeof s, "| %s | %.1fx | %.1fx |", p.name.c_str(), g.tLayout / c.tLayout, g.tTotal / c.tTotal);
      speedups.push_back(s);
    }
  }
  md << "\nSpeed-up of the Voronoi method (C) over the greedy baseline, measured in the same run:\n\n"
        "| pair | layout | total |\n|---|---|---|\n";
  for (const auto& s : speedups) md << s << '\n';
  std::printf("wrote %s, %s and %s\n", (out / "table.csv").c_str(), (out / "table.md").c_str(),
              (out / "table_orders.csv").c_str());
  return 0;
}

/// Every pair of the manifest with greedy and Voronoi C at cbd's defaults, each changed by
/// `variants` (a label per variant and what it changes in the options), each run in its own
/// process: one CSV row per run, `head` naming the columns, the variant's label third (in the
/// log after `what`), then status, E_ang, E_L2, flipped, composed E_ang and E_L2, and `extra`
/// columns before the error. What `sensitivity` and `flipping` share.
using Variant = std::pair<std::string, std::function<void(CrossParameterizationOptions&)>>;
int variantRuns(const fs::path& root, const std::string& manifest, const fs::path& csvPath, const std::string& head,
                const std::string& what, const std::vector<Variant>& variants,
                const std::function<std::string(const Run&)>& extra) {
  std::vector<Pair> pairs;
  if (!readManifest(root, manifest, pairs)) return 1;
  fs::create_directories(csvPath.parent_path());
  std::ofstream csv(csvPath);
  csv << head << '\n';
  for (const Pair& p : pairs) {
    LoadedPair lp;
    if (const std::string why = loadPair(p, lp); !why.empty()) {
      std::printf("%-24s %s\n", p.name.c_str(), why.c_str());
      continue;
    }
    for (const Method& m : methods()) {
      if (m.name != "greedy" && m.name != "voronoi-C") continue;
      for (const Variant& v : variants) {
        CrossParameterizationOptions o = m.options;
        v.second(o);
        const Run r = runPair(lp, o);
        csv << p.name << ',' << m.name << ',' << v.first << ',' << (r.ok ? "ok" : "failed") << ',' << r.eAng << ','
            << r.eL2 << ',' << r.flipped << ',' << r.eAngRaw << ',' << r.eL2Raw << ',' << extra(r) << ",\""
            << r.error << "\"\n";
        csv.flush();
        std::printf("%-22s %-10s %s %s: %s E_ang %.3f E_L2 %.3f flipped %d (composed %.3f %.3f) layout %.3fs total %.1fs %s\n",
                    p.name.c_str(), m.name.c_str(), what.c_str(), v.first.c_str(), r.ok ? "ok    " : "FAILED", r.eAng, r.eL2,
                    r.flipped, r.eAngRaw, r.eL2Raw, r.tLayout, r.tTotal, r.ok ? "" : r.error.c_str());
        std::fflush(stdout);
      }
    }
  }
  std::printf("wrote %s\n", csvPath.c_str());
  return 0;
}

/// The default runs of greedy and Voronoi C once more with each of `rounds` rounds of path
/// straightening (MapUntangleOptions and everything else as cbd's defaults): how far the final
/// map moves with a post-processing setting that both methods share, against the difference
/// between the methods. -> OUTDIR/sensitivity.csv.
int sensitivity(const fs::path& root, const std::string& manifest, const fs::path& out, const std::vector<int>& rounds) {
  std::vector<Variant> variants;
  for (int k : rounds)
    variants.push_back({std::to_string(k), [k](CrossParameterizationOptions& o) { o.straightening.rounds = k; }});
  return variantRuns(root, manifest, out / "sensitivity.csv",
                     "pair,method,straighten_rounds,status,e_ang,e_l2,flipped,e_ang_composed,e_l2_composed,t_total,error",
                     "straighten", variants, [](const Run& r) { return (std::ostringstream() << r.tTotal).str(); });
}

/// What path flipping (greedy_layout.h, step 4) does for each method: greedy with and without
/// its flipping, Voronoi C without (cbd's default) and with it (`flipLayoutPaths`), all else as
/// cbd's defaults, each run in its own process -> OUTDIR/flipping.csv.
int flipping(const fs::path& root, const std::string& manifest, const fs::path& out) {
  std::vector<Variant> variants;
  for (bool flip : {false, true})
    variants.push_back({flip ? "1" : "0", [flip](CrossParameterizationOptions& o) {
                          if (o.method == LayoutMethod::Greedy)
                            o.greedyFlipPaths = flip;
                          else
                            o.flipPaths = flip;
                        }});
  return variantRuns(root, manifest, out / "flipping.csv",
                     "pair,method,flip_paths,status,e_ang,e_l2,flipped,e_ang_composed,e_l2_composed,t_layout,t_total,error",
                     "flip paths", variants, [](const Run& r) { return (std::ostringstream() << r.tLayout << ',' << r.tTotal).str(); });
}

/// The source's faces by their geodesically nearest anchor (multi-source Dijkstra over the
/// edges; a face goes to the anchor nearest to its centroid through one of its corners): the
/// same regions for both methods, whatever their layouts.
std::vector<int> nearestAnchorRegions(const IndexedMesh& s, const std::vector<int>& anchors) {
  const int nv = s.vertexCount();
  std::vector<std::vector<int>> nbr(nv);
  for (const auto& t : s.faces)
    for (int k = 0; k < 3; ++k) nbr[t[k]].push_back(t[(k + 1) % 3]), nbr[t[(k + 1) % 3]].push_back(t[k]);
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<int> from(nv, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  for (size_t i = 0; i < anchors.size(); ++i) {
    dist[anchors[i]] = 0, from[anchors[i]] = static_cast<int>(i);
    q.push({0.0, anchors[i]});
  }
  while (!q.empty()) {
    const auto [d, v] = q.top();
    q.pop();
    if (d > dist[v]) continue;
    for (int w : nbr[v]) {
      const double nd = d + (s.positions[w] - s.positions[v]).norm();
      if (nd < dist[w]) dist[w] = nd, from[w] = from[v], q.push({nd, w});
    }
  }
  std::vector<int> region(s.faceCount(), -1);
  for (int f = 0; f < s.faceCount(); ++f) {
    const auto& t = s.faces[f];
    const Vec3 c = (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]) / 3.0;
    double best = std::numeric_limits<double>::infinity();
    for (int v : t) {
      const double d = dist[v] + (c - s.positions[v]).norm();
      if (from[v] >= 0 && d < best) best = d, region[f] = from[v];
    }
  }
  return region;
}

/// Where on the source the maps of greedy and Voronoi C differ: per pair of the manifest, both
/// methods with cbd's defaults, the final map and the composed one (before untangling: what the
/// base domains and patch maps give), in this process as the per-face terms are needed; each
/// face's share of E_ang and of E_L2^2 summed over the region of its nearest anchor ->
/// OUTDIR/regions.csv. The shares are checked to add up to each run's metrics, which are the
/// table's (same options).
int regions(const fs::path& root, const std::string& manifest, const fs::path& out) {
  std::vector<Pair> pairs;
  if (!readManifest(root, manifest, pairs)) return 1;
  fs::create_directories(out);
  std::ofstream csv(out / "regions.csv");
  // Column order: metric x stage x method, as `sums` is indexed below.
  const char* metric[2] = {"e_ang", "e_l2sq"};
  const char* stage[2] = {"", "_composed"};
  const char* method[2] = {"greedy", "voronoi_c"};
  csv << "pair,anchor,name,faces,area_share";
  for (int st = 0; st < 2; ++st)
    for (int me = 0; me < 2; ++me)
      for (int m = 0; m < 2; ++m) csv << ',' << metric[me] << '_' << method[m] << stage[st];
  csv << '\n';
  csv.precision(10);
  for (const Pair& p : pairs) {
    LoadedPair lp;
    if (const std::string why = loadPair(p, lp); !why.empty()) {
      std::printf("%-24s %s\n", p.name.c_str(), why.c_str());
      continue;
    }
    const IndexedMesh& s = lp.input.source;
    const std::vector<int> region = nearestAnchorRegions(s, lp.sourceAnchors);
    const int na = static_cast<int>(lp.sourceAnchors.size());
    std::vector<double> faces(na, 0), area(na, 0);
    std::vector<std::vector<double>> sums(8, std::vector<double>(na, 0.0));  // [stage][metric][method]
    double totalArea = 0;
    bool ok = true;
    for (const Method& m : methods()) {
      const int mi = m.name == "greedy" ? 0 : m.name == "voronoi-C" ? 1 : -1;
      if (mi < 0) continue;
      const CrossParameterizationResult c = crossParameterize(s, lp.sourceAnchors, lp.input.target, lp.targetAnchors,
                                                              lp.input.report.source.eulerCharacteristic, m.options);
      if (!c.status.ok()) {
        std::printf("%-22s %-10s FAILED %s\n", p.name.c_str(), m.name.c_str(), c.status.message.c_str());
        ok = false;
        break;
      }
      // The final map, then the composed one (before untangling), from the same run.
      for (int st = 0; st < 2; ++st) {
        const DistortionMetrics& dm = st == 0 ? c.metrics : c.composedMetrics;
        // Each face's share of the metrics (distortion.h), summed per region.
        double ang = 0, l2sq = 0;
        for (int f = 0; f < s.faceCount(); ++f) {
          ang += dm.faceAngleShare[f], l2sq += dm.faceL2Share[f];
          if (region[f] < 0) continue;  // no anchor on its component
          sums[4 * st + mi][region[f]] += dm.faceAngleShare[f];
          sums[4 * st + 2 + mi][region[f]] += dm.faceL2Share[f];
        }
        std::printf("%-22s %-10s %-8s E_ang %.4f (faces: %.4f) E_L2 %.4f (faces: %.4f)\n", p.name.c_str(),
                    m.name.c_str(), st ? "composed" : "final", dm.eAng, ang, dm.eL2, std::sqrt(l2sq));
        std::fflush(stdout);
        // The shares must add up to the metrics the table reports, else the regions mean nothing.
        if (std::abs(ang - dm.eAng) > 1e-6 * std::max(1.0, dm.eAng) ||
            std::abs(std::sqrt(l2sq) - dm.eL2) > 1e-6 * dm.eL2) {
          std::printf("%-22s the per-face shares do not add up to the metrics\n", p.name.c_str());
          return 1;
        }
      }
    }
    if (!ok) continue;
    for (int f = 0; f < s.faceCount(); ++f) {
      const auto& t = s.faces[f];
      const double a = 0.5 * (s.positions[t[1]] - s.positions[t[0]]).cross(s.positions[t[2]] - s.positions[t[0]]).norm();
      totalArea += a;
      if (region[f] >= 0) faces[region[f]] += 1, area[region[f]] += a;
    }
    for (int i = 0; i < na; ++i) {
      std::string name = lp.input.report.anchors.source[i].name;
      for (char& ch : name)
        if (ch == ',' || ch == '"') ch = '_';
      csv << p.name << ',' << i << ',' << name << ',' << faces[i] << ',' << area[i] / totalArea;
      for (const auto& v : sums) csv << ',' << v[i];
      csv << '\n';
    }
    csv.flush();
  }
  std::printf("wrote %s\n", (out / "regions.csv").c_str());
  return 0;
}

/// 1-to-4 midpoint subdivision (the same shape at four times the faces).
IndexedMesh subdivide(const IndexedMesh& m) {
  IndexedMesh out = m;
  out.faces.clear();
  std::map<std::pair<int, int>, int> mid;
  auto midpoint = [&](int a, int b) {
    auto key = std::minmax(a, b);
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    out.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
    const int id = static_cast<int>(out.positions.size()) - 1;
    mid.emplace(key, id);
    return id;
  };
  for (const auto& f : m.faces) {
    const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
    out.faces.push_back({f[0], a, c});
    out.faces.push_back({f[1], b, a});
    out.faces.push_back({f[2], c, b});
    out.faces.push_back({a, b, c});
  }
  return out;
}

/// Anchors of the size sweep of `scaling` (farthest-point samples of each subdivision level).
constexpr int kSizeSweepAnchors = 32;

/// Layout time against anchors (on one mesh) and against mesh size (subdivision), both
/// methods, the mesh paired with a turned copy of itself; plus one full Dijkstra sweep as the lower bound.
int scaling(const std::string& meshPath, const fs::path& out, int maxLevel, const std::vector<int>& counts) {
  Mesh vm;
  if (!loadMesh(meshPath, vm).status) {
    std::fprintf(stderr, "cbd_bench: cannot load %s\n", meshPath.c_str());
    return 1;
  }
  const IndexedMesh base = toIndexed(vm);
  const int euler = validateMesh(base, "mesh").eulerCharacteristic;
  fs::create_directories(out);
  std::ofstream csv(out / "scaling.csv");
  csv << "experiment,vertices,anchors,method,status,t_voronoi,t_source_layout,t_target_layout,t_layout,t_dijkstra,peak_mb\n";
  auto sweep = [&](const IndexedMesh& m, const std::vector<int>& a) {
    return forked([&] {
      Run r;
      RefinedMesh rm(m);
      PathTracer tracer(rm, EdgeNodeOptions{});
      PathQuery q;
      q.source = a[0];
      q.distancesOnly = true;
      for (size_t k = 1; k < a.size(); ++k) q.goals.push_back({a[k], {}, 0});
      // Every vertex a goal: the search sweeps the whole edge-node graph once.
      for (int v = 0; v < m.vertexCount(); v += 1) q.goals.push_back({v, {}, 0});
      const auto t0 = std::chrono::steady_clock::now();
      tracer.trace(q);
      r.tTotal = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      r.ok = true;
      return r;
    });
  };
  // The target is the mesh turned a quarter about z (exactly: coordinates swapped): the same
  // surface, but not the same input, so the Voronoi method traces its target layout rather
  // than taking the source's (pipeline.h, LayoutPair::sameSurface).
  auto turnedCopy = [](const IndexedMesh& m) {
    IndexedMesh turned = m;
    for (Vec3& p : turned.positions) p = Vec3(-p.y(), p.x(), p.z());
    return turned;
  };
  auto record = [&](const char* exp, const IndexedMesh& m, int n) {
    const std::vector<int> a = farthestPointSampling(m, n);
    const Run d = sweep(m, a);
    for (const Method& meth : methods()) {
      if (meth.name != "greedy" && meth.name != "voronoi-C") continue;  // layouts only: no straightening
      const IndexedMesh turned = turnedCopy(m);
      const Run r = forked([&] { return runPipeline(m, a, turned, a, euler, meth.options, true); });
      csv << exp << ',' << m.vertexCount() << ',' << n << ',' << meth.name << ',' << (r.ok ? "ok" : "failed") << ','
          << r.tVoronoi << ',' << r.tSource << ',' << r.tTarget << ',' << r.tLayout << ',' << d.tTotal << ','
          << r.peakMB << '\n';
      csv.flush();
      std::printf("%-8s V=%-7d n=%-4d %-10s %s layout %.3fs (one Dijkstra sweep %.3fs) peak %.0f MB\n", exp,
                  m.vertexCount(), n, meth.name.c_str(), r.ok ? "ok" : "FAILED", r.tLayout, d.tTotal, r.peakMB);
      std::fflush(stdout);
    }
  };
  for (int n : counts) record("anchors", base, n);
  IndexedMesh m = base;
  for (int level = 0; level <= maxLevel; ++level) {
    record("size", m, kSizeSweepAnchors);
    if (level < maxLevel) m = subdivide(m);
  }
  std::printf("wrote %s\n", (out / "scaling.csv").c_str());
  // At the largest size (of a size sweep), the whole pipeline of each method (cbd's defaults:
  // layouts, straightening, parameterization, untangling, metrics) for its peak memory.
  if (maxLevel > 0) {
    std::ofstream full(out / "full.csv");
    full << "vertices,anchors,method,status,e_ang,e_l2,flipped,flipped_before_untangle,t_layout,t_total,peak_mb,error\n";
    const std::vector<int> a = farthestPointSampling(m, kSizeSweepAnchors);
    const IndexedMesh turned = turnedCopy(m);
    for (const Method& meth : methods()) {
      if (meth.name != "greedy" && meth.name != "voronoi-C") continue;
      const Run r = forked([&] { return runPipeline(m, a, turned, a, euler, meth.options, false); });
      full << m.vertexCount() << ',' << a.size() << ',' << meth.name << ',' << (r.ok ? "ok" : "failed") << ',' << r.eAng
           << ',' << r.eL2 << ',' << r.flipped << ',' << r.flippedRaw << ',' << r.tLayout << ',' << r.tTotal << ','
           << r.peakMB << ",\"" << r.error << "\"\n";
      full.flush();
      std::printf("full     V=%-7d n=%-4zu %-10s %s total %.1fs peak %.0f MB\n", m.vertexCount(), a.size(),
                  meth.name.c_str(), r.ok ? "ok" : "FAILED", r.tTotal, r.peakMB);
      std::fflush(stdout);
    }
    std::printf("wrote %s\n", (out / "full.csv").c_str());
  }
  return 0;
}

/// Random-anchor stress: success rate of both methods per genus and anchor count.
int stressRuns(const fs::path& out, int setsPerCount, const std::vector<int>& counts) {
  fs::create_directories(out);
  std::ofstream csv(out / "stress.csv"), md(out / "stress.md");
  csv << "genus,pair,anchors,sampling,seed,method,status,flipped,invariants,message\n";
  md << "| genus | pair | anchors | sampling | Voronoi ok | greedy ok | Voronoi 0 flipped |\n|---|---|---|---|---|---|---|\n";
  for (int genus = 0; genus <= 2; ++genus) {
    const stress::SyntheticPair pair = stress::makePair(genus);
    for (int n : counts) {
      for (bool farthest : {true, false}) {
        int okV = 0, okG = 0, zeroFlip = 0, runs = 0;
        for (int k = 0; k < setsPerCount; ++k) {
          const unsigned seed = 1000u * static_cast<unsigned>(n) + static_cast<unsigned>(k);
          const auto sa = stress::randomAnchors(pair.source, n, seed, farthest);
          bool counted = false;
          for (LayoutMethod m : {LayoutMethod::Voronoi, LayoutMethod::Greedy}) {
            const Run r = forked([&] {
              const stress::Outcome o = stress::run(pair, sa, m);
              Run x;
              x.ok = o.ok && o.invariantsHold;
              x.flipped = o.flipped;
              x.error = o.ok ? (o.invariantsHold ? "" : "invariant broken") : std::string(errorCodeName(o.code));
              if (o.code == ErrorCode::AnchorsShareVertex) x.error = "skip";
              return x;
            });
            if (r.error == "skip") break;
            if (!counted) ++runs, counted = true;
            const bool isV = m == LayoutMethod::Voronoi;
            if (r.ok) (isV ? okV : okG)++;
            if (r.ok && isV && r.flipped == 0) ++zeroFlip;
            csv << genus << ",\"" << pair.name << "\"," << n << ',' << (farthest ? "farthest" : "random") << ',' << seed
                << ',' << layoutMethodName(m) << ',' << (r.ok ? "ok" : "failed") << ',' << r.flipped << ','
                << (r.ok ? 1 : 0) << ",\"" << r.error << "\"\n";
          }
        }
        md << "| " << genus << " | " << pair.name << " | " << n << " | " << (farthest ? "farthest-point" : "uniform random")
           << " | " << okV << "/" << runs << " | " << okG << "/" << runs << " | " << zeroFlip << "/" << runs << " |\n";
        std::printf("genus %d n=%-4d %-8s voronoi %d/%d greedy %d/%d (voronoi with 0 flipped: %d)\n", genus, n,
                    farthest ? "farthest" : "random", okV, runs, okG, runs, zeroFlip);
        std::fflush(stdout);
      }
    }
  }
  std::printf("wrote %s and %s\n", (out / "stress.csv").c_str(), (out / "stress.md").c_str());
  return 0;
}

/// "8,16,32" -> {8, 16, 32}.
std::vector<int> intList(const char* s) {
  std::vector<int> out;
  std::stringstream ss(s);
  for (std::string x; std::getline(ss, x, ',');) out.push_back(std::stoi(x));
  return out;
}

}  // namespace

/// The settings the report names, as this build has them: cbd's defaults (the option structs'
/// initialisers, which the table's default runs use) and the bench's own constants ->
/// OUTDIR/defaults.csv, so bench/report.py writes none of them by hand.
int defaults(const fs::path& out) {
  fs::create_directories(out);
  const CrossParameterizationOptions o;
  std::ofstream csv(out / "defaults.csv");
  csv << "setting,value\n"
      << "straighten_rounds," << o.straightening.rounds << '\n'
      << "min_edge_nodes," << o.edgeNodes.minEdgeNodes << '\n'
      << "adaptive_edge_nodes," << (o.edgeNodes.adaptive ? 1 : 0) << '\n'
      << "polish_stretch_weight," << o.untangling.polishStretchWeight << '\n'
      << "flip_paths," << (o.flipPaths ? 1 : 0) << '\n'
      << "greedy_flip_paths," << (o.greedyFlipPaths ? 1 : 0) << '\n'
      << "size_sweep_anchors," << kSizeSweepAnchors << '\n';
  if (!csv) {
    std::fprintf(stderr, "cbd_bench: cannot write %s\n", (out / "defaults.csv").c_str());
    return 1;
  }
  std::printf("wrote %s\n", (out / "defaults.csv").c_str());
  return 0;
}

int main(int argc, char** argv) {
  const fs::path root = fs::path(argc > 0 ? argv[0] : ".").parent_path();
  // --help: the usage on stdout, exit 0; a wrong command line: on stderr, exit 2.
  const bool help = argc == 2 && (std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0);
  auto usage = [help] {
    std::fprintf(help ? stdout : stderr,
                 "usage: cbd_bench table ROOT MANIFEST OUTDIR [ORDERS]\n"
                 "       cbd_bench scaling MESH OUTDIR MAX_SUBDIVISION_LEVEL N1,N2,...\n"
                 "       cbd_bench stress OUTDIR SETS_PER_COUNT N1,N2,...\n"
                 "       cbd_bench sensitivity ROOT MANIFEST OUTDIR R1,R2,...\n"
                 "       cbd_bench regions ROOT MANIFEST OUTDIR\n"
                 "       cbd_bench flipping ROOT MANIFEST OUTDIR\n"
                 "       cbd_bench defaults OUTDIR\n"
                 "table: for every pair of the manifest, the greedy baseline and the Voronoi method (E1: one\n"
                 "edge node per edge; C: adaptive) -> OUTDIR/table.csv, OUTDIR/table.md; greedy and C also\n"
                 "with ORDERS - 1 (default 2) more seeded polish vertex orders -> OUTDIR/table_orders.csv.\n"
                 "scaling: layout time against anchor count (N1,N2,... farthest-point anchors on MESH) and\n"
                 "against mesh size (MESH and its 1-to-4 subdivisions up to MAX_SUBDIVISION_LEVEL, %d anchors),\n"
                 "with one full Dijkstra sweep of the edge-node graph as the lower bound -> OUTDIR/scaling.csv;\n"
                 "with a subdivision level > 0, also the whole pipeline at the largest size -> OUTDIR/full.csv.\n"
                 "stress: random and farthest-point anchor sets on synthetic genus 0/1/2 pairs, both methods\n"
                 "-> OUTDIR/stress.csv, OUTDIR/stress.md.\n"
                 "sensitivity: greedy and Voronoi C on every pair of the manifest with each of R1, R2, ...\n"
                 "rounds of path straightening -> OUTDIR/sensitivity.csv.\n"
                 "regions: greedy and Voronoi C (defaults; final and composed map) on every pair of the\n"
                 "manifest, each source face's share of E_ang and of E_L2^2 summed per region of its nearest\n"
                 "anchor -> OUTDIR/regions.csv.\n"
                 "flipping: greedy with and without its path flipping, Voronoi C without (the default) and with\n"
                 "it (--flip-paths) on every pair of the manifest -> OUTDIR/flipping.csv.\n"
                 "defaults: cbd's default settings and the bench's constants that the report names\n"
                 "-> OUTDIR/defaults.csv.\n",
                 kSizeSweepAnchors);
    return help ? 0 : 2;
  };
  (void)root;
  if (argc >= 5 && std::strcmp(argv[1], "table") == 0) return table(argv[2], argv[3], argv[4], argc >= 6 ? std::max(1, std::atoi(argv[5])) : 3);
  if (argc >= 6 && std::strcmp(argv[1], "scaling") == 0) {
    return scaling(argv[2], argv[3], std::stoi(argv[4]), intList(argv[5]));
  }
  if (argc >= 5 && std::strcmp(argv[1], "stress") == 0) {
    return stressRuns(argv[2], std::stoi(argv[3]), intList(argv[4]));
  }
  if (argc >= 6 && std::strcmp(argv[1], "sensitivity") == 0) {
    return sensitivity(argv[2], argv[3], argv[4], intList(argv[5]));
  }
  if (argc >= 5 && std::strcmp(argv[1], "regions") == 0) return regions(argv[2], argv[3], argv[4]);
  if (argc >= 5 && std::strcmp(argv[1], "flipping") == 0) return flipping(argv[2], argv[3], argv[4]);
  if (argc >= 3 && std::strcmp(argv[1], "defaults") == 0) return defaults(argv[2]);
  return usage();
}
