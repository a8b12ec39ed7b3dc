#pragma once
/// @file jobs.h
/// The commands of the front ends, one call each: files in, files out. Contract:
///  * inputs are only read; every file a job writes is known before it runs (`outputFiles`), so
///    a front end can refuse an output that would replace an input;
///  * a job checks its input first, then prepares the output folder (and checks that the
///    caller's report file can be written), then computes, and writes only once every stage
///    succeeded; a job that fails or is cancelled writes no file and removes the folders it
///    created while they are still empty;
///  * `progress` sees every stage; when it says stop the job ends with ErrorCode::Cancelled;
///  * the result holds everything a report needs (report.h turns it into JSON and lines).

#include <string>
#include <vector>

#include "cbd/pipeline.h"
#include "cbd/progress.h"
#include "cbd/validate_input.h"

namespace cbd {

/// `cbd layout`: the base domain of one surface, or of a source/target pair.
struct LayoutJob {
  InputFiles files;                      ///< targetMesh / targetAnchors empty: the source alone
  ValidationOptions validation;
  CrossParameterizationOptions pipeline;
  std::string outDir;
  /// A file the caller writes after the job (its JSON report), checked to be writable before
  /// the computation as the outputs are; "" or "-": none.
  std::string reportPath;
  bool paired() const { return !files.targetMesh.empty(); }
};

struct LayoutJobResult {
  Status status;
  bool computed = false;            ///< the input was valid and the computation started
  LoadedSurface single;             ///< the source alone (when not paired)
  SourceLayoutResult singleLayout;  ///< its layout and counters
  LoadedInput input;                ///< both surfaces (when paired)
  LayoutPair layouts;               ///< their layouts; one surface: its added anchors and warnings
                                    ///< (the layout itself is in `singleLayout`)
  StageTimes times;                 ///< `total` includes loading and writing
};

/// The files `runLayoutJob` writes: layout.ply, paths.ply, clusters.ply in `outDir` (one
/// surface) or in its source/ and target/ folders.
std::vector<std::string> outputFiles(const LayoutJob& job);

void runLayoutJob(const LayoutJob& job, LayoutJobResult& out, const Progress& progress = {});

/// `cbd map`: the cross-parameterization of a source/target pair.
struct MapJob {
  InputFiles files;
  ValidationOptions validation;
  CrossParameterizationOptions pipeline;
  std::string outDir;
  int morphFrames = 0;  ///< 0: none, else in kMorphFramesRange
  std::string reportPath;  ///< as in LayoutJob
};
inline constexpr IntRange kMorphFramesRange{2, 1000};

struct MapJobResult {
  Status status;
  bool computed = false;  ///< the input was valid and the computation started
  LoadedInput input;
  CrossParameterizationResult result;
  /// M_ts (the target's vertices on the source) against the target: its face stretch is in
  /// mts.ply, its flips in the report.
  DistortionMetrics inverse;
  int staleMorphFrames = 0;  ///< frames of an earlier, longer morph sequence removed
};

/// The files `runMapJob` writes (mst.ply, mts.ply, correspondence.txt, both layouts, the morph
/// frames) and the later frames of an earlier morph sequence in `outDir`, which it removes.
std::vector<std::string> outputFiles(const MapJob& job);

void runMapJob(const MapJob& job, MapJobResult& out, const Progress& progress = {});

/// `cbd sample-anchors`: anchors spread over one surface, written as a PickPoints file.
struct SampleJob {
  std::string mesh;
  int count = 0;      ///< at least 1
  int seed = 0;       ///< the first anchor's vertex (one some face uses)
  std::string out;    ///< the .pp file
};

struct SampleJobResult {
  Status status;
  LoadedSurface surface;
  std::vector<Anchor> anchors;        ///< written (fewer than `count` on a small mesh: see warnings)
  std::vector<std::string> warnings;  ///< the mesh's and the sampling's
};

void runSampleJob(const SampleJob& job, SampleJobResult& out);

}  // namespace cbd
