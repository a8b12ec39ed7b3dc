#pragma once
/// @file report.h
/// What a run tells its user, the same from every front end. Contract:
///  * JSON: the objects of the CLI's `--json` reports (keys are stable: scripts read them);
///  * lines: the human-readable report, one result per line, led by a one-word label padded to
///    eight columns ("map     E_ang ...", "untangle flipped ..."; continuation lines indented),
///    as the CLI prints them and the plugin logs them;
///  * warnings: what the user should check although the run succeeded;
///  * `summary`: the one line that says how good the map is (E_ang, E_L2, flips, time).
/// Nothing here computes: it only formats results of the stages and jobs.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cbd/jobs.h"
#include "cbd/pipeline.h"
#include "cbd/validate_input.h"

namespace cbd {

using Json = nlohmann::json;

// --- JSON

Json toJson(const MeshReport& mesh);
/// The layout section of a report: counts, detour, and the method's own counters.
Json toJson(const LayoutPair& layouts);
/// Seconds per stage ("timing_s").
Json toJson(const StageTimes& times);
/// Distortion metrics ("metrics").
Json toJson(const DistortionMetrics& metrics);

/// `cbd check`: both meshes with their anchor counts, and the matched anchors with their snap
/// distances (when the pair is valid).
Json checkJson(const InputReport& report);
/// `cbd layout` (without "status" and "message", which the front end adds).
Json layoutJobJson(const LayoutJob& job, const LayoutJobResult& result);
/// `cbd map` (the same).
Json mapJobJson(const MapJob& job, const MapJobResult& result);

// --- lines

/// A mesh: "<role>  <path>: V vertices, F faces, genus g".
std::string meshLine(const char* role, const std::string& path, const MeshReport& mesh);
/// `cbd check`'s report of a valid pair (mesh lines, anchors, verdict).
std::vector<std::string> checkLines(const InputFiles& files, const InputReport& report);
/// The layouts: method, edges, patches, paths of each kind, detour, flips.
std::vector<std::string> layoutLines(const LayoutPair& layouts);
/// Straightening, smoothing, the map's metrics and the map stage's own counts. `inverse`:
/// M_ts's metrics when computed (their flips are reported with an optimized map).
std::vector<std::string> mapLines(const CrossParameterizationResult& result, const CrossParameterizationOptions& options,
                                  const DistortionMetrics* inverse = nullptr);
/// "time    voronoi 0.012 s, ..." (`withMap`: the map's stages too).
std::string timesLine(const StageTimes& times, bool withMap);
/// A layout job's lines after a successful run, including the files written.
std::vector<std::string> layoutJobLines(const LayoutJob& job, const LayoutJobResult& result);
/// A map job's lines after a successful run, including the files written.
std::vector<std::string> mapJobLines(const MapJob& job, const MapJobResult& result);

/// What a successful layout or map run warns about (detours, mesh warnings).
std::vector<std::string> layoutWarnings(const LayoutPair& layouts);
std::vector<std::string> inputWarnings(const InputReport& report);

/// "E_ang 0.1742 (9.98 deg), E_L2 1.2344, 0 flipped, 6.31 s": how good the map is, in a line.
std::string summary(const DistortionMetrics& metrics, double seconds);

/// `value` with `digits` decimals ("%.*f").
std::string fixed(double value, int digits);

}  // namespace cbd
