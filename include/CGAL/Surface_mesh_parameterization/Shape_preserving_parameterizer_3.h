// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SHAPE_PRESERVING_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SHAPE_PRESERVING_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/Fixed_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/shape_preserving_weights.h>

#include <CGAL/Default.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/SparseLU>

#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Floater's shape-preserving parameterization (M. S. Floater, "Parametrization and smooth
/// approximation of surface triangulations", CAGD 14, 1997 \cgalCite{cgal:f-psast-97}): a
/// fixed-border parameterizer whose weights are convex combinations obtained from the geodesic
/// polar map of each one-ring.
/// The weights are positive, so with a convex border the result is one-to-one (Tutte, Floater),
/// and a planar mesh whose border is fixed at its own positions is reproduced exactly.
///
/// CGAL's `Mean_value_coordinates_parameterizer_3` is Floater's later (2003) method
/// \cgalCite{cgal:f-mvc-03}; this class is the 1997 one, which Yoshizawa et al. (2004) use as
/// the starting point of the stretch minimization (`Stretch_minimizing_parameterizer_3`).
///
/// The weights of a vertex come from its whole one-ring at once: they are computed once per
/// vertex and served to the neighbour-by-neighbour interface of the base class.
/// A cone vertex whose flattened ring has an angle above \f$ \pi \f$ (where the construction is
/// undefined) gets mean-value weights instead.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (a triangle mesh)
/// \tparam BorderParameterizer_ a model of `Parameterizer_3` that fixes the border (convex for
///         a one-to-one result). <b>%Default:</b>
/// \code
///   Square_border_arc_length_parameterizer_3<TriangleMesh_>
/// \endcode
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraTraits_d`. <b>%Default:</b> a sparse LU
///         factorization, faster and more robust than CGAL's default iterative solver here:
/// \code
///   CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
///                                             Eigen::COLAMDOrdering<int> > >
/// \endcode
///
/// \sa `CGAL::Surface_mesh_parameterization::Stretch_minimizing_parameterizer_3`
template <class TriangleMesh_,
          class BorderParameterizer_ = Default,
          class SolverTraits_ = Default>
class Shape_preserving_parameterizer_3
  : public Fixed_border_parameterizer_3<
      TriangleMesh_,
      typename Default::Get<BorderParameterizer_,
                            Square_border_arc_length_parameterizer_3<TriangleMesh_> >::type,
      typename Default::Get<SolverTraits_,
                            CGAL::Eigen_solver_traits<
                              Eigen::SparseLU<Eigen_sparse_matrix<double>::EigenType,
                                              Eigen::COLAMDOrdering<int> > > >::type>
{
public:
#ifndef DOXYGEN_RUNNING
  typedef typename Default::Get<BorderParameterizer_,
                                Square_border_arc_length_parameterizer_3<TriangleMesh_> >::type
                                                              Border_parameterizer;
  typedef typename Default::Get<SolverTraits_,
                                CGAL::Eigen_solver_traits<
                                  Eigen::SparseLU<Eigen_sparse_matrix<double>::EigenType,
                                                  Eigen::COLAMDOrdering<int> > > >::type
                                                              Solver_traits;
#else
  /// Border parameterizer type
  typedef BorderParameterizer_                                Border_parameterizer;
  /// Solver traits type
  typedef SolverTraits_                                       Solver_traits;
#endif

  /// Triangle mesh type
  typedef TriangleMesh_                                       Triangle_mesh;
  /// Triangle mesh type (the spelling of CGAL's parameterizers)
  typedef TriangleMesh_                                       TriangleMesh;

  /// Mesh vertex type
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor   vertex_descriptor;
  /// Mesh halfedge type
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

private:
  typedef Fixed_border_parameterizer_3<Triangle_mesh, Border_parameterizer, Solver_traits> Base;
  typedef typename Base::NT                                   NT;
  typedef typename Base::PPM                                  PPM;

public:
  /// Constructor.
  /// \param border_param object that maps the border to the plane
  /// \param sparse_la traits object giving access to the sparse linear solver
  Shape_preserving_parameterizer_3(Border_parameterizer border_param = Border_parameterizer(),
                                   Solver_traits sparse_la = Solver_traits())
    : Base(border_param, sparse_la)
  { }

  /// Computes a one-to-one mapping (if the border is convex) from the connected component of
  /// `bhd` to the plane; see `Fixed_border_parameterizer_3::parameterize()`.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and a 2D point as value
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `int` as value
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `bool` as value
  ///
  /// \param mesh the triangle mesh
  /// \param bhd a halfedge on the border of the component to parameterize
  /// \param uvmap receives the position in the plane of every vertex of the component
  /// \param vimap numbers the vertices of the component (the rows of the linear system)
  /// \param vpmap receives `true` for every parameterized vertex
  ///
  /// \returns `OK`, or the error of the border parameterizer or of the solver
  ///
  /// \pre `mesh` is a triangle mesh and the component of `bhd` a topological disk.
  /// \pre `vimap` numbers the vertices of that component from 0 (as `parameterize()` does).
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap vimap,
                          VertexParameterizedMap vpmap)
  {
    m_cached_valid = false;
    return Base::parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }

protected:
  /// Returns the shape-preserving weight \f$ \lambda_{ij} \f$ of the neighbour
  /// `neighbor_vertex_v_j` of `main_vertex_v_i`. The weights of the whole ring are computed on
  /// the first query of a vertex (the query for the neighbour
  /// `source(halfedge(main_vertex_v_i, mesh), mesh)`, where a walk around the ring starts); NaN
  /// if they are undefined (a zero-length edge, fewer than three neighbours).
  virtual NT compute_w_ij(const Triangle_mesh& mesh,
                          vertex_descriptor main_vertex_v_i,
                          Vertex_around_target_circulator<Triangle_mesh> neighbor_vertex_v_j) const
  {
    // Callers walk the ring from halfedge(v_i): a query for that first neighbour starts a new
    // walk, so the ring is recomputed then and never served stale from an earlier call.
    if(!m_cached_valid || m_cached_vertex != main_vertex_v_i
       || *neighbor_vertex_v_j == source(halfedge(main_vertex_v_i, mesh), mesh))
      compute_ring(mesh, main_vertex_v_i);
    for(std::size_t k = 0; k < m_neighbors.size(); ++k)
      if(m_neighbors[k] == *neighbor_vertex_v_j)
        return NT(m_weights[k]);
    return NT(std::numeric_limits<double>::quiet_NaN()); // not a neighbour
  }

private:
  void compute_ring(const Triangle_mesh& mesh, vertex_descriptor v) const
  {
    const PPM ppmap = get(vertex_point, mesh);
    auto to_vec = [](const auto& p) {
      return internal::Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    };
    m_neighbors.clear();
    m_ring.clear();
    for(vertex_descriptor w : vertices_around_target(halfedge(v, mesh), mesh)) {
      m_neighbors.push_back(w);
      m_ring.push_back(to_vec(get(ppmap, w)));
    }
    if(!m_computer.compute(to_vec(get(ppmap, v)), m_ring, m_weights))
      m_weights.assign(m_ring.size(), std::numeric_limits<double>::quiet_NaN());
    m_cached_vertex = v;
    m_cached_valid = true;
  }

  // one-ring cache: Fixed_border_parameterizer_3 asks for the weights neighbour by neighbour
  mutable internal::Shape_preserving_ring_weights m_computer;
  mutable std::vector<vertex_descriptor> m_neighbors;
  mutable std::vector<internal::Vec3> m_ring;
  mutable std::vector<double> m_weights;
  mutable vertex_descriptor m_cached_vertex;
  mutable bool m_cached_valid = false;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_SHAPE_PRESERVING_PARAMETERIZER_3_H
