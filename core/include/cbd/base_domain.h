#pragma once
/// @file base_domain.h
/// The common base domain D as a surface of its own: one equilateral triangle per patch (corner
/// k at `domainCorner(k)`), glued along the layout's edges. Two equilateral triangles glued along
/// a side unfold rigidly into one plane, so D is flat everywhere except at its vertices, the
/// anchors (cone points of angle 60 degrees times their valence). A point of D is a patch and a
/// point of its triangle; moving it is a straight walk that continues across sides into the
/// neighbouring triangles' frames.
///
/// Contract: every chart map between two patch frames is a rotation by a multiple of 60 degrees
/// plus a translation by a vector of the triangular lattice (kept as integers, so composing any
/// number of them is exact); `walk` ends in the triangle that holds the end point (on a shared
/// side, either); `SurfaceInDomain` maps D onto one surface and back with its patch
/// parameterization (a bijection), to rounding.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "cbd/layout.h"
#include "cbd/parameterization.h"

namespace cbd {

/// A rigid motion of the plane that maps the triangular lattice spanned by (1, 0) and
/// (1/2, sqrt(3)/2) onto itself: x -> R(60 degrees * rot) x + a (1, 0) + b (1/2, sqrt(3)/2).
struct ChartMap {
  int rot = 0;     ///< 0..5
  int a = 0, b = 0;
  Eigen::Matrix2d linear() const;
  Vec2 apply(const Vec2& x) const { return linear() * x + translation(); }
  Vec2 translation() const;
  /// (this * o)(x) = this(o(x)).
  ChartMap operator*(const ChartMap& o) const;
  ChartMap inverse() const;
  bool operator==(const ChartMap& o) const { return rot == o.rot && a == o.a && b == o.b; }
  bool operator!=(const ChartMap& o) const { return !(*this == o); }
};

/// A point of D: a patch and a point of its triangle, in that patch's frame.
struct DomainPoint {
  int patch = -1;
  Vec2 uv = Vec2::Zero();
};

/// The patches of a layout glued into D.
class BaseDomain {
 public:
  /// Pre-condition: `validateLayout` holds (every layout edge is a side of two patch sides).
  explicit BaseDomain(const Layout& layout);

  int patchCount() const { return static_cast<int>(next_.size()); }
  /// The patch across side k (corner k -> k + 1) of patch p, and the map from p's frame into its
  /// frame (p's triangle lands outside the neighbour's, sharing the side).
  int neighbour(int p, int k) const { return next_[p][k]; }
  const ChartMap& across(int p, int k) const { return across_[p][k]; }
  /// The side of patch p that is layout edge e and borders patch q (-1: none).
  int sideOf(int p, int e, int q) const;
  /// Area of D: the patches' triangles.
  double area() const;

  /// Move `point` by `d` (in its patch's frame), following the straight line across sides. On
  /// return `point` is the end point in the frame of the triangle holding it, and `toStart` (if
  /// given) maps that frame into the frame the walk started in. False when the walk does not end
  /// within a bound proportional to the patch count (a broken invariant upstream).
  bool walk(DomainPoint& point, Vec2 d, ChartMap* toStart = nullptr) const;

 private:
  std::vector<std::array<int, 3>> next_;
  std::vector<std::array<ChartMap, 3>> across_;
  std::vector<std::array<int, 3>> edge_;
};

/// Signed distance-like coordinate of uv from side k of the domain triangle (positive inside).
double insideSide(const Vec2& uv, int k);

/// One surface mapped onto D by its layout and patch parameterization (both outlive this).
class SurfaceInDomain {
 public:
  SurfaceInDomain(const Layout& layout, const PatchParameterization& param, const BaseDomain& domain);

  /// Where a point of D lies on the surface.
  struct Hit {
    FacePoint point;              ///< input face + barycentric coordinates
    Vec3 position = Vec3::Zero();
    /// d position / d uv of the parameterization face holding the point (3 x 2, the patch's frame).
    Eigen::Matrix<double, 3, 2> jacobian = Eigen::Matrix<double, 3, 2>::Zero();
    /// The smallest barycentric coordinate in that face: near 0 the point is near an edge, where
    /// the parameterization's Jacobian jumps.
    double edgeCloseness = 1.0;
    /// The surface's area per area of D there (interpolated from its mean over each
    /// parameterization vertex's star, so that it varies continuously over D) and its gradient
    /// along u and v.
    double density = 1.0;
    Vec2 densitySlope = Vec2::Zero();
  };
  /// False when no face of the patch holds the point (a bug upstream).
  bool locate(const DomainPoint& p, Hit& hit) const;
  /// The point of D of input vertex v (on a path: in one of its patches; an anchor: at a corner).
  /// Unreferenced vertices: patch -1.
  DomainPoint vertexPoint(int v) const;
  /// The point of D of a point of the input surface (face + barycentric coordinates).
  bool toDomain(const FacePoint& p, DomainPoint& out) const;

  /// The layout (its refined mesh is the surface in D: every face inside one patch).
  const Layout& layout() const { return layout_; }
  /// For every face of the layout's refined mesh (each inside one patch), the chart maps that take
  /// its corners' frames into the frame of the face's patch.
  std::vector<std::array<ChartMap, 3>> faceCharts() const;

 private:
  /// The map from the frame of patch `from` into the frame of patch `to` at refined vertex v,
  /// which lies on both (on their shared path, or an anchor corner of both).
  ChartMap transitionAt(int v, int from, int to) const;
  const Layout& layout_;
  const PatchParameterization& param_;
  const BaseDomain& domain_;
  PatchLocator locator_;
  std::vector<int> vertexFace_;       // a refined face around every refined vertex (-1: none)
  std::vector<int> vertexPath_;       // layout edge of a path vertex, -1 off paths / anchors
  std::vector<int> childBegin_, child_;  // refined faces of each input face (CSR)
  std::vector<double> density_;         // per refined vertex: its star's area over its area in D
};

/// A closed triangle mesh immersed in D (its vertices at points of D, each face's corners
/// brought into one frame by its chart maps, as `SurfaceInDomain::faceCharts` makes them),
/// indexed for point location: which face holds a point of D. Meant for an injective immersion,
/// where every point of D lies in one face (or on the faces sharing its edge or vertex).
class TrianglesInDomain {
 public:
  TrianglesInDomain(const BaseDomain& domain, const std::vector<std::array<int, 3>>& faces,
                    const std::vector<DomainPoint>& points, const std::vector<std::array<ChartMap, 3>>& charts);
  /// The face holding p and p's barycentric coordinates in it. False when no face does (only
  /// for an immersion that does not cover D).
  bool locate(const DomainPoint& p, FacePoint& out) const;

 private:
  struct Entry {
    int face;
    std::array<Vec2, 3> corner;  // in the patch's frame
  };
  struct Grid {
    int n = 1;
    std::vector<std::vector<int>> cells;
    std::vector<Entry> entries;
  };
  std::vector<Grid> grids_;
};

}  // namespace cbd
