#include "cbd/anchors.h"
#include "cbd/files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include <pugixml.hpp>

namespace cbd {
namespace {

int lineOfOffset(const std::string& text, std::ptrdiff_t offset) {
  if (offset < 0) return 0;
  offset = std::min<std::ptrdiff_t>(offset, static_cast<std::ptrdiff_t>(text.size()));
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
}

bool parseDouble(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end && *end == '\0' && std::isfinite(out);
}

bool parseInt(const std::string& s, long long& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtoll(s.c_str(), &end, 10);
  return end && *end == '\0';
}

Status duplicateCheck(const AnchorSet& set) {
  std::unordered_map<std::string, int> seen;
  for (const Anchor& a : set.anchors) {
    auto [it, inserted] = seen.emplace(a.name, a.line);
    if (!inserted) {
      return Status::error(ErrorCode::DuplicateAnchorName,
                           set.source + ": anchor name '" + a.name + "' appears twice (lines " +
                               std::to_string(it->second) + " and " + std::to_string(a.line) +
                               "); give every anchor a unique name");
    }
  }
  return Status::success();
}

AnchorSet parsePickedPoints(const std::string& text, const std::string& label) {
  AnchorSet set;
  set.source = label;
  set.format = AnchorFormat::PickedPoints;
  pugi::xml_document doc;
  pugi::xml_parse_result res = doc.load_buffer(text.data(), text.size(),
                                               pugi::parse_default | pugi::parse_doctype);
  if (!res) {
    set.status = Status::error(ErrorCode::MalformedAnchors,
                               label + ": malformed XML at line " +
                                   std::to_string(lineOfOffset(text, res.offset)) + ": " +
                                   res.description() + " (re-save the points with MeshLab's PickPoints tool)");
    return set;
  }
  pugi::xml_node root = doc.child("PickedPoints");
  if (!root) {
    set.status = Status::error(ErrorCode::MalformedAnchors,
                               label + ": not a MeshLab PickedPoints file (no <PickedPoints> root element)");
    return set;
  }
  int index = 0;
  for (pugi::xml_node p = root.child("point"); p; p = p.next_sibling("point")) {
    ++index;
    const int line = lineOfOffset(text, p.offset_debug());
    Anchor a;
    a.line = line;
    a.name = p.attribute("name").as_string();
    if (a.name.empty()) a.name = std::to_string(index);
    double xyz[3];
    const char* keys[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      pugi::xml_attribute at = p.attribute(keys[k]);
      if (!at || !parseDouble(at.as_string(), xyz[k])) {
        set.status = Status::error(ErrorCode::MalformedAnchors,
                                   label + ": line " + std::to_string(line) + ": point '" + a.name +
                                       "' has a missing or non-numeric '" + keys[k] + "' coordinate");
        return set;
      }
    }
    a.position = Vec3(xyz[0], xyz[1], xyz[2]);
    a.hasPosition = true;
    // MeshLab writes active="0" for points the user unchecked; anything else counts as active.
    if (std::string(p.attribute("active").as_string("1")) == "0") {
      ++set.skippedInactive;
      continue;
    }
    set.anchors.push_back(a);
  }
  set.status = duplicateCheck(set);
  return set;
}

std::vector<std::string> tokens(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == '\r') {
      if (!cur.empty()) out.push_back(cur), cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

AnchorSet parseLines(const std::string& text, const std::string& label) {
  AnchorSet set;
  set.source = label;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  bool decided = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    auto tok = tokens(line);
    if (tok.empty()) continue;
    long long idx = 0;
    if (!decided) {
      set.format = (parseInt(tok[0], idx) && (tok.size() == 1 || tok.size() == 4))
                       ? AnchorFormat::VertexList
                       : AnchorFormat::NamedPoints;
      decided = true;
    }
    Anchor a;
    a.line = lineNo;
    auto bad = [&](const std::string& why) {
      set.status = Status::error(ErrorCode::MalformedAnchors,
                                 label + ": line " + std::to_string(lineNo) + ": " + why);
    };
    if (set.format == AnchorFormat::VertexList) {
      if (!parseInt(tok[0], idx) || (tok.size() != 1 && tok.size() != 4)) {
        bad("expected 'vertex_index [x y z]' like the lines before it");
        return set;
      }
      if (idx < 0 || idx > std::numeric_limits<int>::max()) {
        set.status = Status::error(ErrorCode::AnchorIndexOutOfRange,
                                   label + ": line " + std::to_string(lineNo) + ": vertex index " +
                                       tok[0] + " is negative or too large (indices are 0-based)");
        return set;
      }
      a.vertex = static_cast<int>(idx);
      a.name = std::to_string(set.anchors.size() + 1);
      if (tok.size() == 4) {
        double xyz[3];
        for (int k = 0; k < 3; ++k)
          if (!parseDouble(tok[1 + k], xyz[k])) {
            bad("coordinate '" + tok[1 + k] + "' is not a finite number");
            return set;
          }
        a.position = Vec3(xyz[0], xyz[1], xyz[2]);
        a.hasPosition = true;
      }
    } else {
      if (tok.size() != 4) {
        bad("expected 'name x y z' (" + std::to_string(tok.size()) + " fields found)");
        return set;
      }
      double xyz[3];
      for (int k = 0; k < 3; ++k)
        if (!parseDouble(tok[1 + k], xyz[k])) {
          bad("coordinate '" + tok[1 + k] + "' is not a finite number");
          return set;
        }
      a.name = tok[0];
      a.position = Vec3(xyz[0], xyz[1], xyz[2]);
      a.hasPosition = true;
    }
    set.anchors.push_back(a);
  }
  set.status = duplicateCheck(set);
  return set;
}

}  // namespace

AnchorSet parseAnchors(const std::string& text, const std::string& label) {
  // A UTF-8 byte-order mark (Windows editors write one) is not part of the first line.
  const std::string_view bom = "\xEF\xBB\xBF";
  const std::string body = text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text;
  const auto first = body.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && body[first] == '<') return parsePickedPoints(body, label);
  // Lines end in LF, CR LF or a lone CR (classic Mac OS): the line numbers of messages count them all.
  std::string lines;
  lines.reserve(body.size());
  for (size_t i = 0; i < body.size(); ++i) {
    if (body[i] != '\r') lines += body[i];
    else if (i + 1 >= body.size() || body[i + 1] != '\n') lines += '\n';
  }
  return parseLines(lines, label);
}

AnchorSet readAnchors(const std::string& path) {
  // Checked before opening: opening a named pipe would wait for a writer.
  auto notFound = [&path](const std::string& message) {
    AnchorSet set;
    set.source = path;
    set.status = Status::error(ErrorCode::FileNotFound, message);
    return set;
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return notFound("cannot read anchor file '" + path + "': " + notAFileReason(path));
  std::ifstream in(path, std::ios::binary);
  if (!in) return notFound("cannot open anchor file '" + path + "' for reading (check permissions)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parseAnchors(ss.str(), path);
}

Status writePickedPoints(const std::string& path, const std::vector<Anchor>& anchors,
                         const std::string& dataFileName) {
  pugi::xml_document doc;
  doc.append_child(pugi::node_doctype).set_value("PickedPoints");
  pugi::xml_node root = doc.append_child("PickedPoints");
  pugi::xml_node data = root.append_child("DocumentData");
  data.append_child("DataFileName").append_attribute("name") = dataFileName.c_str();
  data.append_child("templateName").append_attribute("name") = "";
  for (const Anchor& a : anchors) {
    pugi::xml_node p = root.append_child("point");
    char buf[64];
    const char* keys[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      std::snprintf(buf, sizeof buf, "%.17g", a.position[k]);
      p.append_attribute(keys[k]) = buf;
    }
    p.append_attribute("active") = "1";
    p.append_attribute("name") = a.name.c_str();
  }
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path tmp = writeTarget(path);
  if (!doc.save_file(tmp.c_str(), "    ")) {
    return Status::error(ErrorCode::OutputError, "cannot write '" + path + "' (check that the folder exists and is writable)");
  }
  if (tmp == target) return Status::success();  // a device, written in place
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return Status::error(ErrorCode::OutputError, "cannot move the finished file into '" + path + "'");
  }
  return Status::success();
}

Status snapAnchors(const IndexedMesh& mesh, const AnchorSet& anchors, double tolerance,
                   const std::string& meshName, std::vector<SnappedAnchor>& out) {
  out.clear();
  std::vector<char> referenced(mesh.positions.size(), 0);
  for (const auto& f : mesh.faces)
    for (int v : f)
      if (v >= 0 && v < mesh.vertexCount()) referenced[v] = 1;
  const double diag = boundingBoxDiagonal(mesh);
  std::unordered_map<int, std::string> owner;
  for (const Anchor& a : anchors.anchors) {
    SnappedAnchor s;
    s.name = a.name;
    if (a.vertex >= 0) {
      if (a.vertex >= mesh.vertexCount()) {
        return Status::error(ErrorCode::AnchorIndexOutOfRange,
                             anchors.source + ": line " + std::to_string(a.line) + ": vertex index " +
                                 std::to_string(a.vertex) + " is out of range for the " + meshName +
                                 " mesh (" + std::to_string(mesh.vertexCount()) +
                                 " vertices, 0-based); is this the anchor file of that mesh?");
      }
      if (!referenced[a.vertex]) {
        return Status::error(ErrorCode::AnchorIndexOutOfRange,
                             anchors.source + ": line " + std::to_string(a.line) + ": vertex " +
                                 std::to_string(a.vertex) + " of the " + meshName +
                                 " mesh belongs to no face; pick a vertex on the surface");
      }
      s.vertex = a.vertex;
      if (a.hasPosition && diag > 0) s.snapDistance = (mesh.positions[a.vertex] - a.position).norm() / diag;
    } else {
      double best = std::numeric_limits<double>::infinity();
      for (int v = 0; v < mesh.vertexCount(); ++v) {
        if (!referenced[v]) continue;
        const double d = (mesh.positions[v] - a.position).squaredNorm();
        if (d < best) best = d, s.vertex = v;
      }
      if (s.vertex < 0) {
        return Status::error(ErrorCode::EmptyMesh, "the " + meshName + " mesh has no faces to snap anchors to");
      }
      s.snapDistance = diag > 0 ? std::sqrt(best) / diag : 0.0;
    }
    if (s.snapDistance > tolerance) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "%.3g%% of the bounding-box diagonal (tolerance %.3g%%)",
                    100.0 * s.snapDistance, 100.0 * tolerance);
      if (a.vertex >= 0)  // an index line whose coordinates are not that vertex's
        return Status::error(ErrorCode::AnchorOffSurface,
                             anchors.source + ": line " + std::to_string(a.line) + ": vertex " +
                                 std::to_string(a.vertex) + " of the " + meshName +
                                 " mesh lies away from the coordinates on the line, at " + buf +
                                 "; is this the anchor file of that mesh, and its vertex order unchanged? (or "
                                 "raise --snap-tolerance)");
      return Status::error(ErrorCode::AnchorOffSurface,
                           anchors.source + ": anchor '" + a.name + "' (line " + std::to_string(a.line) +
                               ") is off the " + meshName + " surface: its nearest vertex is " +
                               std::to_string(s.vertex) + " at " + buf +
                               "; is this the anchor file of that mesh? (or raise --snap-tolerance)");
    }
    auto [it, inserted] = owner.emplace(s.vertex, a.name);
    if (!inserted) {
      return Status::error(ErrorCode::AnchorsShareVertex,
                           anchors.source + ": anchors '" + it->second + "' and '" + a.name +
                               "' snap to the same vertex " + std::to_string(s.vertex) + " of the " +
                               meshName + " mesh; move one of them or remove the duplicate");
    }
    out.push_back(s);
  }
  return Status::success();
}

Status matchAnchors(const AnchorSet& source, const AnchorSet& target, std::vector<int>& sourceIndex,
                    std::vector<int>& targetIndex) {
  sourceIndex.clear();
  targetIndex.clear();
  if (Status s = duplicateCheck(source); !s) return s;
  if (Status s = duplicateCheck(target); !s) return s;
  // No point at all, or every one unchecked in PickPoints: say so rather than that names do not
  // match.
  for (const AnchorSet* set : {&source, &target}) {
    if (!set->anchors.empty()) continue;
    if (set->skippedInactive == 0)
      return Status::error(ErrorCode::TooFewAnchors,
                           set->source + ": no anchors in the file (no <point> element, or no data line); corresponding "
                                         "anchors must be given on both meshes");
    return Status::error(ErrorCode::TooFewAnchors,
                         set->source + ": all " + std::to_string(set->skippedInactive) +
                             " points are inactive (active=\"0\", unchecked in MeshLab's PickPoints); check the "
                             "points to use as anchors (and save the .pp file again, if the points come from one)");
  }
  std::unordered_map<std::string, int> inTarget;
  for (size_t i = 0; i < target.anchors.size(); ++i) inTarget.emplace(target.anchors[i].name, static_cast<int>(i));
  std::vector<std::string> onlySource, onlyTarget;
  std::unordered_set<std::string> inSource;
  for (size_t i = 0; i < source.anchors.size(); ++i) {
    const std::string& n = source.anchors[i].name;
    inSource.insert(n);
    auto it = inTarget.find(n);
    if (it == inTarget.end()) {
      onlySource.push_back(n);
      continue;
    }
    sourceIndex.push_back(static_cast<int>(i));
    targetIndex.push_back(it->second);
  }
  for (const Anchor& a : target.anchors)
    if (!inSource.count(a.name)) onlyTarget.push_back(a.name);
  if (!onlySource.empty() || !onlyTarget.empty()) {
    const bool src = !onlySource.empty();
    const auto& list = src ? onlySource : onlyTarget;
    sourceIndex.clear();
    targetIndex.clear();
    return Status::error(
        ErrorCode::AnchorNameMismatch,
        "anchor '" + list.front() + "' is in " + (src ? source.source : target.source) + " but not in " +
            (src ? target.source : source.source) + " (" + std::to_string(onlySource.size()) +
            " source-only and " + std::to_string(onlyTarget.size()) +
            " target-only names); corresponding anchors must have the same name on both meshes" +
            (source.skippedInactive + target.skippedInactive > 0
                 ? " (inactive points, active=\"0\", were left out: " + std::to_string(source.skippedInactive) +
                       " of the source's, " + std::to_string(target.skippedInactive) + " of the target's)"
                 : std::string()));
  }
  return Status::success();
}

}  // namespace cbd
