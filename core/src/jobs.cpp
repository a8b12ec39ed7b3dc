#include "cbd/jobs.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "cbd/anchor_sampling.h"
#include "cbd/files.h"
#include "cbd/layout_io.h"
#include "cbd/map_io.h"

namespace cbd {
namespace {

namespace fs = std::filesystem;

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<int> vertices(const std::vector<SnappedAnchor>& anchors) {
  std::vector<int> v;
  for (const SnappedAnchor& a : anchors) v.push_back(a.vertex);
  return v;
}

/// The output folder and the caller's report file, checked before the computation.
Status prepareOutputs(OutputFolder& folder, const std::string& outDir, const std::string& reportPath) {
  if (Status s = folder.prepare(outDir); !s) return s;
  return checkWritableFile(reportPath, "JSON report");
}

Status cancelledWhile(const char* what) { return Status::error(ErrorCode::Cancelled, std::string("cancelled while ") + what); }

/// A cancelled job says that it wrote nothing.
Status withNothingWritten(Status s) {
  if (s.code == ErrorCode::Cancelled) s.message += "; nothing was written";
  return s;
}

void layoutFiles(const fs::path& dir, std::vector<std::string>& out) {
  for (const char* name : {kLayoutFile, kPathsFile, kClustersFile}) out.push_back((dir / name).string());
}

}  // namespace

std::vector<std::string> outputFiles(const LayoutJob& job) {
  std::vector<std::string> files;
  const fs::path out(job.outDir);
  if (job.paired()) {
    layoutFiles(out / kSourceLayoutFolder, files);
    layoutFiles(out / kTargetLayoutFolder, files);
  } else {
    layoutFiles(out, files);
  }
  return files;
}

void runLayoutJob(const LayoutJob& job, LayoutJobResult& out, const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  out.status = Status::success();
  out.computed = false;
  OutputFolder folder;
  auto fail = [&](const Status& s) {
    out.status = withNothingWritten(s);
    folder.abandon();
    out.times.total = seconds(t0);
  };
  if (!progress.report(0.0, "reading the input")) return fail(cancelledWhile("reading the input"));
  if (!job.paired()) {
    if (job.pipeline.method == LayoutMethod::Greedy)
      return fail(Status::error(ErrorCode::InvalidArgument,
                                "the greedy method builds both layouts at once: give a target mesh and its anchors"));
    if (Status s = validate(job.pipeline); !s) return fail(s);
    loadSurface(job.files.sourceMesh, job.files.sourceAnchors, "source", job.validation, out.single);
    if (!out.single.status) return fail(out.single.status);
    if (Status s = prepareOutputs(folder, job.outDir, job.reportPath); !s) return fail(s);
    out.computed = true;
    // The mesh paired with itself: buildLayouts then builds one layout (and adds anchor pairs
    // where it gets stuck, each pair one vertex).
    CrossParameterizationOptions o = job.pipeline;
    o.anchorNames.clear();
    for (const SnappedAnchor& a : out.single.anchors) o.anchorNames.push_back(a.name);
    const std::vector<int> anchors = vertices(out.single.anchors);
    out.layouts = buildLayouts(out.single.indexed, anchors, out.single.indexed, anchors,
                               out.single.report.eulerCharacteristic, o, progress.part(0.05, 0.95));
    out.times = out.layouts.times;
    out.singleLayout = std::move(out.layouts.sourceStats);
    if (!out.layouts.status) return fail(out.layouts.status);
    out.singleLayout.layout = std::move(out.layouts.source);
    out.layouts.target = Layout{};
    if (!progress.report(0.95, "writing the layout")) return fail(cancelledWhile("building the layout"));
    if (Status s = writeLayout(out.singleLayout.layout, job.outDir); !s) return fail(s);
  } else {
    if (Status s = validate(job.pipeline); !s) return fail(s);
    loadAndValidate(job.files, job.validation, out.input);
    if (!out.input.report.status) return fail(out.input.report.status);
    if (Status s = prepareOutputs(folder, job.outDir, job.reportPath); !s) return fail(s);
    out.computed = true;
    CrossParameterizationOptions o = job.pipeline;
    o.anchorNames = out.input.report.anchors.names;
    out.layouts = buildLayouts(out.input.source, vertices(out.input.report.anchors.source), out.input.target,
                               vertices(out.input.report.anchors.target), out.input.report.source.eulerCharacteristic, o,
                               progress.part(0.05, 0.95));
    out.times = out.layouts.times;
    if (!out.layouts.status) return fail(out.layouts.status);
    if (!progress.report(0.95, "writing the layouts")) return fail(cancelledWhile("building the layouts"));
    if (Status s = writeLayout(out.layouts.source, (fs::path(job.outDir) / kSourceLayoutFolder).string()); !s) return fail(s);
    if (Status s = writeLayout(out.layouts.target, (fs::path(job.outDir) / kTargetLayoutFolder).string()); !s) return fail(s);
  }
  progress.report(1.0, "done");
  out.times.total = seconds(t0);
}

std::vector<std::string> outputFiles(const MapJob& job) {
  const fs::path out(job.outDir);
  std::vector<std::string> files;
  for (const char* name : {kMstFile, kMtsFile, kCorrespondenceFile}) files.push_back((out / name).string());
  layoutFiles(out / kSourceLayoutFolder, files);
  layoutFiles(out / kTargetLayoutFolder, files);
  for (int k = 0; k < job.morphFrames; ++k) files.push_back((out / morphFileName(k)).string());
  if (job.morphFrames > 0)
    for (const std::string& stale : staleMorphFrames(job.outDir, job.morphFrames)) files.push_back(stale);
  return files;
}

void runMapJob(const MapJob& job, MapJobResult& out, const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  out.status = Status::success();
  out.staleMorphFrames = 0;
  out.computed = false;
  OutputFolder folder;
  auto fail = [&](const Status& s) {
    out.status = withNothingWritten(s);
    folder.abandon();
    out.result.times.total = seconds(t0);
  };
  if (!progress.report(0.0, "reading the input")) return fail(cancelledWhile("reading the input"));
  if (Status s = validate(job.pipeline); !s) return fail(s);
  if (job.morphFrames != 0 && !kMorphFramesRange.contains(job.morphFrames))
    return fail(Status::error(ErrorCode::InvalidArgument, "the morph frames must be 0 (none) or in " +
                                                              std::to_string(kMorphFramesRange.lo) + ".." +
                                                              std::to_string(kMorphFramesRange.hi)));
  LoadedInput& in = out.input;
  loadAndValidate(job.files, job.validation, in);
  if (!in.report.status) return fail(in.report.status);
  if (Status s = prepareOutputs(folder, job.outDir, job.reportPath); !s) return fail(s);
  out.computed = true;
  CrossParameterizationOptions o = job.pipeline;
  o.anchorNames = in.report.anchors.names;
  const std::vector<int> sa = vertices(in.report.anchors.source), ta = vertices(in.report.anchors.target);
  out.result = crossParameterize(in.source, sa, in.target, ta, in.report.source.eulerCharacteristic, o,
                                 progress.part(0.02, 0.95));
  if (!out.result.status) return fail(out.result.status);
  const CrossParameterizationResult& r = out.result;
  if (!progress.report(0.95, "writing the outputs")) return fail(cancelledWhile("mapping"));

  // M_st with the target's attributes, M_ts with the source's.
  out.inverse = computeDistortion(in.target, r.map.targetImage, in.source, r.map.targetToSource);
  const TransferOptions toSource{in.targetLoad.hasVertexColor, in.targetLoad.hasVertexQuality, in.targetLoad.hasVertexTexCoord};
  const TransferOptions toTarget{in.sourceLoad.hasVertexColor, in.sourceLoad.hasVertexQuality, in.sourceLoad.hasVertexTexCoord};
  Mesh mst, mts;
  buildMappedMesh(in.sourceMesh, r.map.sourceImage, r.map.sourceToTarget, in.targetMesh, toSource, r.metrics.faceStretch, mst);
  buildMappedMesh(in.targetMesh, r.map.targetImage, r.map.targetToSource, in.sourceMesh, toTarget, out.inverse.faceStretch, mts);
  auto plyOptions = [](const TransferOptions& t) {
    SavePlyOptions po;
    po.faceColor = po.faceQuality = true;
    po.vertexColor = t.vertexColor;
    po.vertexQuality = t.vertexQuality;
    po.vertexTexCoord = t.vertexTexCoord;
    return po;
  };
  const fs::path dir(job.outDir);
  if (Status s = savePly((dir / kMstFile).string(), mst, plyOptions(toSource)); !s) return fail(s);
  if (Status s = savePly((dir / kMtsFile).string(), mts, plyOptions(toTarget)); !s) return fail(s);
  if (Status s = writeCorrespondence((dir / kCorrespondenceFile).string(), r.map.sourceToTarget, r.map.sourceImage); !s)
    return fail(s);
  if (Status s = writeLayout(r.layouts.source, (dir / kSourceLayoutFolder).string()); !s) return fail(s);
  if (Status s = writeLayout(r.layouts.target, (dir / kTargetLayoutFolder).string()); !s) return fail(s);
  if (job.morphFrames > 0)
    if (Status s = writeMorph(job.outDir, in.sourceMesh, r.map.sourceImage, sa, job.morphFrames, &out.staleMorphFrames); !s)
      return fail(s);
  progress.report(1.0, "done");
  out.result.times.total = seconds(t0);
}

void runSampleJob(const SampleJob& job, SampleJobResult& out) {
  out.status = Status::success();
  out.anchors.clear();
  out.warnings.clear();
  if (job.count < 1)
    return void(out.status = Status::error(ErrorCode::InvalidArgument, "the anchor count must be at least 1"));
  // Anchors are for meshes `map` accepts; a NaN coordinate would be written as a "nan" anchor.
  loadSurface(job.mesh, "", "", ValidationOptions{}, out.surface);
  out.warnings = out.surface.report.warnings;
  if (!out.surface.status) return void(out.status = out.surface.status);
  const IndexedMesh& im = out.surface.indexed;
  if (job.seed < 0 || job.seed >= im.vertexCount())
    return void(out.status = Status::error(ErrorCode::InvalidArgument,
                                           "the seed vertex " + std::to_string(job.seed) + " is not a vertex of '" + job.mesh +
                                               "' (0.." + std::to_string(im.vertexCount() - 1) + ")"));
  // The sampling would start elsewhere, silently, from a vertex no face uses.
  if (std::none_of(im.faces.begin(), im.faces.end(),
                   [&](const auto& f) { return f[0] == job.seed || f[1] == job.seed || f[2] == job.seed; }))
    return void(out.status = Status::error(ErrorCode::InvalidArgument,
                                           "the seed vertex " + std::to_string(job.seed) + " is an unreferenced vertex of '" +
                                               job.mesh + "' (no face uses it): choose a vertex of the surface"));
  const std::vector<int> vs = farthestPointSampling(im, job.count, job.seed);
  if (static_cast<int>(vs.size()) < job.count)
    out.warnings.push_back("'" + job.mesh + "' has only " + std::to_string(vs.size()) + " vertices on its surface: " +
                           std::to_string(vs.size()) + " anchors written, not " + std::to_string(job.count));
  for (size_t k = 0; k < vs.size(); ++k) {
    Anchor a;
    a.name = "a" + std::to_string(k + 1);
    a.position = im.positions[vs[k]];
    out.anchors.push_back(a);
  }
  out.status = writePickedPoints(job.out, out.anchors, fs::path(job.mesh).filename().string());
}

}  // namespace cbd
