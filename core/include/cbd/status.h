#pragma once
/// @file status.h
/// Typed errors of every pipeline stage. Bad input is a result, never a crash:
/// every result struct carries a `Status` as its first field.

#include <string>

namespace cbd {

/// What went wrong. Each value is one class of problem with one remedy; the CLI turns it
/// into a distinct exit code (`exitCode`) and the plugin into a MeshLab error message.
enum class ErrorCode {
  Ok = 0,
  // files and arguments
  InvalidArgument,       ///< an option is out of range or inconsistent
  FileNotFound,          ///< an input file does not exist or cannot be read
  UnsupportedFormat,     ///< file extension not one of the supported formats
  MalformedMesh,         ///< a mesh file cannot be parsed (truncated, bad header)
  OutputError,           ///< an output file or folder cannot be written
  // mesh validity
  EmptyMesh,             ///< no vertices or no faces
  NotTriangles,          ///< the file has faces with more than three vertices
  InvalidCoordinates,    ///< NaN or infinite vertex coordinates
  DegenerateFace,        ///< a face with (near) zero area or a repeated vertex
  DuplicateFace,         ///< two faces on the same three vertices
  OpenBoundary,          ///< an edge used by one face only (the surface is not closed)
  NonManifoldEdge,       ///< an edge used by more than two faces
  NonManifoldVertex,     ///< the faces around a vertex form more than one fan
  InconsistentOrientation, ///< two faces traverse a shared edge in the same direction
  MultipleComponents,    ///< the surface has more than one connected component
  GenusMismatch,         ///< source and target surfaces have different genus
  // anchors
  MalformedAnchors,      ///< an anchor file cannot be parsed (malformed XML, bad line)
  AnchorNameMismatch,    ///< an anchor name appears on one side only
  DuplicateAnchorName,   ///< a name appears twice in one anchor file
  AnchorIndexOutOfRange, ///< a vertex index is outside the mesh
  AnchorOffSurface,      ///< an anchor lies farther from the mesh than the snap tolerance
  AnchorsShareVertex,    ///< two anchors snap to the same vertex
  TooFewAnchors,         ///< fewer than three anchors (or none active)
  TooManyAnchors,        ///< more anchors than the smaller mesh has vertices
  // algorithm
  LayoutFailed,          ///< a common base domain could not be completed
  InternalError,         ///< a broken invariant: a bug, please report it
  // Added after the first release: appended, so that no earlier exit code moves.
  OrientationMismatch,   ///< one surface's faces point outward, the other's inward
  Cancelled              ///< the progress callback asked to stop (Ctrl-C, MeshLab's cancel)
};

/// Outcome of a stage: `code == Ok` or a message naming the problem and the fix.
struct Status {
  ErrorCode code = ErrorCode::Ok;
  std::string message;

  bool ok() const { return code == ErrorCode::Ok; }
  explicit operator bool() const { return ok(); }
  static Status success() { return {}; }
  static Status error(ErrorCode c, std::string msg) { return {c, std::move(msg)}; }
};

/// Stable snake_case name of a code, used in JSON (`"status"`) and logs, e.g. "open_boundary".
const char* errorCodeName(ErrorCode code);

/// One-line description of a code (what it means), as listed by `cbd exit-codes` and README.
const char* errorCodeDescription(ErrorCode code);

/// All codes in enum order (for listings and tests).
const ErrorCode* allErrorCodes(int& count);

/// A count with its noun in the singular for one, for messages: counted(1, "vertex", "vertices")
/// is "1 vertex", counted(3, ...) "3 vertices".
std::string counted(long long n, const char* one, const char* many);

/// Process exit code of the CLI for a code: 0 for Ok, 2 for invalid arguments,
/// 10 + the enum value otherwise (distinct per class, documented in README).
int exitCode(ErrorCode code);

}  // namespace cbd
