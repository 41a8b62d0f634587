// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark only (not part of the package): row (c) of the tables of Yoshizawa, Belyaev and
// Seidel (2004), the intrinsic parameterization of Desbrun, Meyer and Alliez (2002) with a
// fixed border: a linear blend of the Dirichlet (discrete conformal, cotangent) weights and of
// the chi (discrete authalic) weights, lambda = mu = 1/2 by default.

#ifndef SMP_BENCHMARK_INTRINSIC_PARAMETERIZER_3_H
#define SMP_BENCHMARK_INTRINSIC_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/Fixed_border_parameterizer_3.h>
#include <CGAL/Weights/authalic_weights.h>
#include <CGAL/Weights/cotangent_weights.h>
#include <CGAL/boost/graph/iterator.h>

namespace SMP_benchmark {

/// A `Fixed_border_parameterizer_3` whose weight of the neighbour `v_j` of `v_i` is
/// `lambda * w_conformal + mu * w_authalic`, each computed exactly as CGAL's
/// `Discrete_conformal_map_parameterizer_3` and `Discrete_authalic_parameterizer_3` compute
/// theirs (`CGAL::Weights::cotangent_weight` and `CGAL::Weights::authalic_weight`, halved).
///
/// Beware: the cotangent weight is dimensionless, the authalic weight scales as
/// 1 / length^2, so the blend depends on the units of the mesh (on a mesh of small edges the
/// authalic part dominates). This is the blend as Desbrun et al. define it; the benchmark
/// reports the ratio of the two parts on each mesh.
template <class TriangleMesh_,
          class BorderParameterizer_ = CGAL::Default,
          class SolverTraits_ = CGAL::Default>
class Intrinsic_parameterizer_3
  : public CGAL::Surface_mesh_parameterization::Fixed_border_parameterizer_3<
      TriangleMesh_, BorderParameterizer_, SolverTraits_>
{
  typedef CGAL::Surface_mesh_parameterization::Fixed_border_parameterizer_3<
    TriangleMesh_, BorderParameterizer_, SolverTraits_>           Base;

public:
  typedef typename Base::Border_parameterizer                     Border_parameterizer;
  typedef typename Base::Solver_traits                            Solver_traits;
  typedef TriangleMesh_                                           Triangle_mesh;
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;

protected:
  typedef typename Base::NT                                       NT;
  typedef typename Base::PPM                                      PPM;
  typedef typename Base::Point_3                                  Point_3;

public:
  explicit Intrinsic_parameterizer_3(double lambda = 0.5, double mu = 0.5,
                                     Border_parameterizer border_param = Border_parameterizer(),
                                     Solver_traits sparse_la = Solver_traits())
    : Base(border_param, sparse_la), m_lambda(lambda), m_mu(mu)
  { }

  double lambda() const { return m_lambda; }
  double mu() const { return m_mu; }

  /// The two parts of the weight, for diagnostics: {conformal, authalic}.
  static std::pair<NT, NT> weights(const Triangle_mesh& mesh, vertex_descriptor v_i,
                                   CGAL::Vertex_around_target_circulator<Triangle_mesh> v_j)
  {
    const PPM ppmap = get(CGAL::vertex_point, mesh);
    CGAL::Vertex_around_target_circulator<Triangle_mesh> v_k = v_j, v_l = v_j;
    --v_k; // previous neighbour
    ++v_l; // next neighbour
    const Point_3& p_i = get(ppmap, v_i);
    const Point_3& p_j = get(ppmap, *v_j);
    const Point_3& p_k = get(ppmap, *v_k);
    const Point_3& p_l = get(ppmap, *v_l);
    // the same calls and the same factor 1/2 as CGAL's Discrete_conformal_map_parameterizer_3
    // and Discrete_authalic_parameterizer_3
    return {CGAL::Weights::cotangent_weight(p_k, p_j, p_l, p_i) / NT(2),
            CGAL::Weights::authalic_weight(p_k, p_j, p_l, p_i) / NT(2)};
  }

protected:
  NT compute_w_ij(const Triangle_mesh& mesh, vertex_descriptor main_vertex_v_i,
                  CGAL::Vertex_around_target_circulator<Triangle_mesh> neighbor_vertex_v_j) const override
  {
    const std::pair<NT, NT> w = weights(mesh, main_vertex_v_i, neighbor_vertex_v_j);
    return NT(m_lambda) * w.first + NT(m_mu) * w.second;
  }

private:
  double m_lambda;
  double m_mu;
};

} // namespace SMP_benchmark

#endif // SMP_BENCHMARK_INTRINSIC_PARAMETERIZER_3_H
