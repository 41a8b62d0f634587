// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SQUARE_BORDER_EAR_AWARE_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SQUARE_BORDER_EAR_AWARE_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Maps the border onto the unit square by arc length, like
/// `Square_border_arc_length_parameterizer_3`, but chooses the four corners so that no face
/// has its three vertices on one side of the square wherever possible.
///
/// With any polygonal border, a face whose three vertices land on one straight side (a border
/// ear, or a face cut off by an interior edge joining two vertices of one side) gets zero area
/// in every fixed-border method: infinite stretch, and a hole in the texture. Putting a corner
/// at the middle vertex of such a face makes it a proper triangle. The corners start at the
/// border vertices closest to the quarters of the border length (as CGAL does); each face that
/// would be flattened then asks for a corner at one of its vertices, and the move that removes
/// the most such faces, then strays least from the quarters, is taken until none helps.
/// When more faces need a corner than four corners can serve (e.g. five ears), the rest are
/// counted in `number_of_flattened_faces()`.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (a triangle mesh)
///
/// It is used as the border parameterizer of a fixed-border method, e.g.
/// \code
///   typedef SMP::Square_border_ear_aware_parameterizer_3<Mesh>        Border;
///   typedef SMP::Shape_preserving_parameterizer_3<Mesh, Border>       Initializer;
///   SMP::Stretch_minimizing_parameterizer_3<Mesh, Initializer>         parameterizer;
/// \endcode
///
/// \sa `Square_border_arc_length_parameterizer_3`
template <class TriangleMesh_>
class Square_border_ear_aware_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                  Triangle_mesh;
  /// Triangle mesh type (the spelling of CGAL's parameterizers)
  typedef TriangleMesh_                                                  TriangleMesh;
  /// Mesh vertex type
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor   vertex_descriptor;
  /// Mesh halfedge type
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

private:
  typedef typename boost::graph_traits<Triangle_mesh>::face_descriptor     face_descriptor;
  typedef std::array<int, 4>                                               Corners;

public:
  /// Places the vertices of the border of `bhd` on the unit square and sets them in `vpmap`.
  ///
  /// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and a 2D point as value
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `int` as value
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `bool` as value
  ///
  /// \param mesh the triangle mesh
  /// \param bhd a halfedge on the border to parameterize
  /// \param uvmap receives the position on the square of every vertex of the border
  /// \param vimap vertex index map, passed on to CGAL's square border parameterizer
  /// \param vpmap receives `true` for every vertex of the border
  ///
  /// \returns `OK`, or `ERROR_BORDER_TOO_SHORT` for a border of fewer than four vertices or of
  /// zero length.
  ///
  /// \pre `bhd` is a border halfedge of `mesh` (a null halfedge gives `ERROR_BORDER_TOO_SHORT`).
  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVMap uvmap,
                          VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    m_flattened = 0;
    if(bhd == halfedge_descriptor())
      return ERROR_BORDER_TOO_SHORT;
    std::vector<vertex_descriptor> loop; // loop[k] = source of the k-th border halfedge
    std::vector<double> s;               // arc length at loop[k], as a fraction of the total
    const auto vpm = get(CGAL::vertex_point, mesh);
    double length = 0.;
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) {
      loop.push_back(source(h, mesh));
      s.push_back(length);
      const auto& p = get(vpm, source(h, mesh));
      const auto& q = get(vpm, target(h, mesh));
      const double dx = CGAL::to_double(q.x()) - CGAL::to_double(p.x());
      const double dy = CGAL::to_double(q.y()) - CGAL::to_double(p.y());
      const double dz = CGAL::to_double(q.z()) - CGAL::to_double(p.z());
      length += std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    const int n = int(loop.size());
    if(n < 4 || !(length > 0.))
      return ERROR_BORDER_TOO_SHORT;
    for(double& x : s)
      x /= length;

    collect_border_faces(mesh, loop);
    Corners c;
    for(int j = 0; j < 4; ++j) { // closest to the quarters, distinct and in order
      int best = 0;
      for(int k = 1; k < n; ++k)
        if(std::abs(s[k] - j / 4.) < std::abs(s[best] - j / 4.))
          best = k;
      c[j] = best;
    }
    if(!(c[0] < c[1] && c[1] < c[2] && c[2] < c[3]))
      c = {0, n / 4, n / 2, (3 * n) / 4};
    improve(c, s);
    m_flattened = flattened(c).size();

    for(vertex_descriptor v : loop)
      put(vpmap, v, false); // CGAL's square border finds the corners through vpmap
    Square_border_arc_length_parameterizer_3<Triangle_mesh> square(loop[c[0]], loop[c[1]], loop[c[2]], loop[c[3]]);
    return square.parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }

  /// Faces of the last call that still have their three vertices on one side of the square.
  std::size_t number_of_flattened_faces() const { return m_flattened; }

  /// The border is a square, hence convex.
  bool is_border_convex() const { return true; }

private:
  // the faces with three border vertices, by the positions of their vertices along the loop
  void collect_border_faces(const Triangle_mesh& mesh, const std::vector<vertex_descriptor>& loop)
  {
    auto position = get(CGAL::dynamic_vertex_property_t<int>(), mesh); // index + 1; 0: not on the loop
    for(std::size_t k = 0; k < loop.size(); ++k)
      put(position, loop[k], int(k) + 1);
    m_faces.clear();
    for(vertex_descriptor v : loop)
      for(face_descriptor f : faces_around_target(halfedge(v, mesh), mesh)) {
        if(f == boost::graph_traits<Triangle_mesh>::null_face())
          continue;
        std::array<int, 3> t;
        int k = 0;
        bool on_border = true;
        for(vertex_descriptor w : vertices_around_face(halfedge(f, mesh), mesh)) {
          if(k == 3 || get(position, w) == 0) { on_border = false; break; }
          t[k++] = get(position, w) - 1;
        }
        if(on_border && k == 3) {
          std::sort(t.begin(), t.end());
          m_faces.push_back(t);
        }
      }
    std::sort(m_faces.begin(), m_faces.end());
    m_faces.erase(std::unique(m_faces.begin(), m_faces.end()), m_faces.end());
  }

  // true if the loop positions a, b, c all lie on the side [c_i, c_{i+1}] (cyclic)
  static bool on_one_side(const std::array<int, 3>& t, const Corners& c, int n)
  {
    for(int i = 0; i < 4; ++i) {
      const int from = c[i], span = (c[(i + 1) % 4] - c[i] + n) % n;
      bool all = true;
      for(int p : t)
        all = all && (p - from + n) % n <= span;
      if(all)
        return true;
    }
    return false;
  }

  std::vector<std::array<int, 3> > flattened(const Corners& c) const
  {
    std::vector<std::array<int, 3> > out;
    for(const auto& t : m_faces)
      if(on_one_side(t, c, m_n))
        out.push_back(t);
    return out;
  }

  // how far the corners stray from the quarters, measured from the first corner
  static double deviation(const Corners& c, const std::vector<double>& s)
  {
    double d = 0.;
    for(int j = 1; j < 4; ++j) {
      double x = s[c[j]] - s[c[0]];
      if(x < 0.) x += 1.;
      d += std::abs(x - j / 4.);
    }
    return d;
  }

  static bool in_order(const Corners& c, int n)
  {
    int turns = 0; // corners must go once around the loop, each at its own vertex
    for(int j = 0; j < 4; ++j) {
      const int gap = (c[(j + 1) % 4] - c[j] + n) % n;
      if(gap == 0) return false;
      turns += gap;
    }
    return turns == n;
  }

  void improve(Corners& c, const std::vector<double>& s)
  {
    m_n = int(s.size());
    std::size_t count = flattened(c).size();
    double dev = deviation(c, s);
    for(;;) {
      Corners best = c;
      std::size_t best_count = count;
      double best_dev = dev;
      for(const auto& t : flattened(c))
        for(int j = 0; j < 4; ++j)
          for(int p : t) {
            Corners trial = c;
            trial[j] = p;
            if(!in_order(trial, m_n))
              continue;
            const std::size_t k = flattened(trial).size();
            const double d = deviation(trial, s);
            if(k < best_count || (k == best_count && k < count && d < best_dev)) {
              best = trial;
              best_count = k;
              best_dev = d;
            }
          }
      if(best_count >= count)
        return;
      c = best;
      count = best_count;
      dev = best_dev;
    }
  }

  std::vector<std::array<int, 3> > m_faces;
  int m_n = 0;
  std::size_t m_flattened = 0;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_SQUARE_BORDER_EAR_AWARE_PARAMETERIZER_3_H
