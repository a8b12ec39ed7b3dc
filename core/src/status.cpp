#include "cbd/status.h"

#include <filesystem>

namespace cbd {

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::Ok: return "ok";
    case ErrorCode::InvalidArgument: return "invalid_argument";
    case ErrorCode::FileNotFound: return "file_not_found";
    case ErrorCode::UnsupportedFormat: return "unsupported_format";
    case ErrorCode::MalformedMesh: return "malformed_mesh";
    case ErrorCode::OutputError: return "output_error";
    case ErrorCode::EmptyMesh: return "empty_mesh";
    case ErrorCode::NotTriangles: return "not_triangles";
    case ErrorCode::InvalidCoordinates: return "invalid_coordinates";
    case ErrorCode::DegenerateFace: return "degenerate_face";
    case ErrorCode::DuplicateFace: return "duplicate_face";
    case ErrorCode::OpenBoundary: return "open_boundary";
    case ErrorCode::NonManifoldEdge: return "non_manifold_edge";
    case ErrorCode::NonManifoldVertex: return "non_manifold_vertex";
    case ErrorCode::InconsistentOrientation: return "inconsistent_orientation";
    case ErrorCode::MultipleComponents: return "multiple_components";
    case ErrorCode::GenusMismatch: return "genus_mismatch";
    case ErrorCode::MalformedAnchors: return "malformed_anchors";
    case ErrorCode::AnchorNameMismatch: return "anchor_name_mismatch";
    case ErrorCode::DuplicateAnchorName: return "duplicate_anchor_name";
    case ErrorCode::AnchorIndexOutOfRange: return "anchor_index_out_of_range";
    case ErrorCode::AnchorOffSurface: return "anchor_off_surface";
    case ErrorCode::AnchorsShareVertex: return "anchors_share_vertex";
    case ErrorCode::TooFewAnchors: return "too_few_anchors";
    case ErrorCode::TooManyAnchors: return "too_many_anchors";
    case ErrorCode::LayoutFailed: return "layout_failed";
    case ErrorCode::InternalError: return "internal_error";
    case ErrorCode::OrientationMismatch: return "orientation_mismatch";
    case ErrorCode::Cancelled: return "cancelled";
  }
  return "internal_error";
}

const char* errorCodeDescription(ErrorCode code) {
  switch (code) {
    case ErrorCode::Ok: return "success";
    case ErrorCode::InvalidArgument: return "an option is out of range or inconsistent";
    case ErrorCode::FileNotFound: return "an input file does not exist or cannot be read";
    case ErrorCode::UnsupportedFormat: return "file extension not one of the supported formats";
    case ErrorCode::MalformedMesh: return "a mesh file cannot be parsed (truncated, bad header)";
    case ErrorCode::OutputError: return "an output file or folder cannot be written";
    case ErrorCode::EmptyMesh: return "no vertices or no faces";
    case ErrorCode::NotTriangles: return "the file has faces with more than three vertices";
    case ErrorCode::InvalidCoordinates: return "NaN or infinite vertex coordinates";
    case ErrorCode::DegenerateFace: return "a face with (near) zero area or a repeated vertex";
    case ErrorCode::DuplicateFace: return "two faces on the same three vertices";
    case ErrorCode::OpenBoundary: return "an edge used by one face only (the surface is not closed)";
    case ErrorCode::NonManifoldEdge: return "an edge used by more than two faces";
    case ErrorCode::NonManifoldVertex: return "the faces around a vertex form more than one fan";
    case ErrorCode::InconsistentOrientation: return "two faces traverse a shared edge in the same direction";
    case ErrorCode::MultipleComponents: return "the surface has more than one connected component";
    case ErrorCode::GenusMismatch: return "source and target surfaces have different genus";
    case ErrorCode::MalformedAnchors: return "an anchor file cannot be parsed (malformed XML, bad line)";
    case ErrorCode::AnchorNameMismatch: return "an anchor name appears on one side only";
    case ErrorCode::DuplicateAnchorName: return "a name appears twice in one anchor file";
    case ErrorCode::AnchorIndexOutOfRange: return "a vertex index is outside the mesh";
    case ErrorCode::AnchorOffSurface: return "an anchor lies farther from the mesh than the snap tolerance";
    case ErrorCode::AnchorsShareVertex: return "two anchors snap to the same vertex";
    case ErrorCode::TooFewAnchors: return "fewer than three anchors (or none active)";
    case ErrorCode::TooManyAnchors: return "more anchors than the smaller mesh has vertices";
    case ErrorCode::LayoutFailed: return "a common base domain could not be completed";
    case ErrorCode::InternalError: return "a broken invariant: a bug, please report it";
    case ErrorCode::OrientationMismatch: return "one surface's faces point outward, the other's inward";
    case ErrorCode::Cancelled: return "the run was cancelled; nothing was written";
  }
  return "";
}

const ErrorCode* allErrorCodes(int& count) {
  static const ErrorCode codes[] = {ErrorCode::Ok, ErrorCode::InvalidArgument, ErrorCode::FileNotFound, ErrorCode::UnsupportedFormat, ErrorCode::MalformedMesh, ErrorCode::OutputError, ErrorCode::EmptyMesh, ErrorCode::NotTriangles, ErrorCode::InvalidCoordinates, ErrorCode::DegenerateFace, ErrorCode::DuplicateFace, ErrorCode::OpenBoundary, ErrorCode::NonManifoldEdge, ErrorCode::NonManifoldVertex, ErrorCode::InconsistentOrientation, ErrorCode::MultipleComponents, ErrorCode::GenusMismatch, ErrorCode::MalformedAnchors, ErrorCode::AnchorNameMismatch, ErrorCode::DuplicateAnchorName, ErrorCode::AnchorIndexOutOfRange, ErrorCode::AnchorOffSurface, ErrorCode::AnchorsShareVertex, ErrorCode::TooFewAnchors, ErrorCode::TooManyAnchors, ErrorCode::LayoutFailed, ErrorCode::InternalError, ErrorCode::OrientationMismatch, ErrorCode::Cancelled};
  count = static_cast<int>(sizeof(codes) / sizeof(codes[0]));
  return codes;
}

std::string counted(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

int exitCode(ErrorCode code) {
  if (code == ErrorCode::Ok) return 0;
  if (code == ErrorCode::InvalidArgument) return 2;
  return 10 + static_cast<int>(code);
}

}  // namespace cbd
