// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_PARAMETERIZER_3_H

// The package's main class. Longer than most headers because it is the reference documentation
// of the method and of its options (much of its length); the iteration's parts (weights,
// stretch, solver, polish) live in internal headers.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_options.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_report.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Exposed_initializer.h>
#include <CGAL/Surface_mesh_parameterization/internal/polish_stage.h>
#include <CGAL/Surface_mesh_parameterization/internal/Shared_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/Stopping_rule.h>
#include <CGAL/Surface_mesh_parameterization/internal/Stretch_minimizing_settings.h>
#include <CGAL/Surface_mesh_parameterization/internal/Stretch_update_ratios.h>
#include <CGAL/Surface_mesh_parameterization/internal/component_vertex_index.h>
#include <CGAL/Surface_mesh_parameterization/internal/Weighted_laplacian_system.h>
#include <CGAL/Surface_mesh_parameterization/internal/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_named_parameters.h>
#include <CGAL/Surface_mesh_parameterization/internal/ring_weights.h>

#include <CGAL/Default.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/circulator.h>

#include <Eigen/SparseLU>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// The stretch-minimizing parameterization of S. Yoshizawa, A. Belyaev and H.-P. Seidel,
/// "A moving mesh approach to stretch-minimizing mesh parameterization"
/// \cgalCite{cgal:ybs-mmasm-05}, first presented as "A fast and simple stretch-minimizing mesh
/// parameterization" (Shape Modeling International 2004) \cgalCite{cgal:ybs-fssmm-04}.
///
/// Starting from a fixed-border parameterization with positive weights \f$ w^0_{ij} \f$
/// (\f$ U^0 \f$: by default Floater's shape-preserving weights on the unit square), each step
/// computes the L2 stretch \f$ \sigma_j \f$ of every vertex (Sander et al. 2001
/// \cgalCite{cgal:ssgh-tmpm-01}, area-weighted over the faces around it), divides the
/// weights by \f$ \sigma_j^{\eta} \f$ and solves again:
/// \f$ w^{h+1}_{ij} = w^h_{ij} / \sigma_j(U^h)^{\eta} \f$. A vertex of high stretch pulls its
/// neighbours less, so the regions of high stretch get more room in the plane. The iteration
/// stops when the normalized L2 stretch of the mesh stops decreasing
/// (a decrease below a relative \f$ 10^{-10} \f$, at the level of rounding, counts as none),
/// and the best parameterization \f$ U^{opt} \f$ is written; one step gives \f$ U^1 \f$.
/// The weights stay positive, so with a convex border no face flips at any step.
///
/// A mesh with several boundaries (a sphere with holes, an annulus) is handled as in the
/// paper's section 4: the border of `bhd` is fixed, and every other boundary is closed by a
/// virtual fan around its centroid that exists only in the linear system, so that its vertices
/// are interior vertices with positive weights (shape-preserving weights over the closed ring,
/// whatever the initializer) and the no-flip guarantee still holds. The mesh is not modified.
///
/// Faces of zero area in 3D or in the plane (e.g. a border ear whose three vertices land on
/// one side of the square) are left out of the vertex stretch and of the stopping measure,
/// and counted in the report.
///
/// Beyond the paper, named parameters choose other start weights, another stretch update and
/// another rule for a step that does not help, and a polish after \f$ U^{opt} \f$ that lowers
/// Sander's stretch energy directly and keeps every face positive, with the border fixed or free
/// (then never crossing itself): cheap descent steps (projected Newton steps on u and v apart with
/// the border fixed, along a fixed proxy with the border free), then projected Newton steps.
/// `Stretch_minimizing_preset::LOWEST_STRETCH` sets the start, the update and the descent steps.
///
/// The border, the initial weights and the solver are chosen through the template parameters;
/// options are named parameters given to the constructor (`CGAL::Surface_mesh_parameterization::parameterize()`
/// copies the parameterizer, so options travel inside it) or to `parameterize()` for one call.
/// After a call, `report()` tells the stretch of every step, the step kept and why the
/// iteration ended. Copies of a parameterizer share that report, so it can be read after
/// `CGAL::Surface_mesh_parameterization::parameterize()` too. Copies also share the sparse
/// solver (`CGAL::Eigen_solver_traits` holds it by a shared pointer): calls on copies made on
/// several threads are safe but run one at a time, and the report is the one of the call that
/// ended last. To parameterize on several threads at once, construct a parameterizer per thread.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (a triangle mesh, e.g. `Surface_mesh`,
///         `Polyhedron_3` or `Seam_mesh`)
/// \tparam InitialParameterizer_ a class derived from `Fixed_border_parameterizer_3` whose
///         weights are non-negative with a positive sum around every vertex
///         (`Shape_preserving_parameterizer_3`, `Mean_value_coordinates_parameterizer_3`, ...).
///         Its border parameterizer fixes the border; only its weights are used, the linear
///         systems are solved here.
///         <b>%Default:</b>
/// \code
///   Shape_preserving_parameterizer_3<TriangleMesh_, Square_border_arc_length_parameterizer_3<TriangleMesh_> >
/// \endcode
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` for an Eigen sparse solver `S` (direct or
///         iterative; its pattern is analysed once per call, its factorization serves both
///         coordinates), or any model of CGAL's concept `SparseLinearAlgebraWithFactorTraits_d`
///         (`factor()` at every step, then `linear_solver()` for each coordinate). <b>%Default:</b>
///         `CGAL::Eigen_solver_traits` of an internal wrapper of `Eigen::SparseLU` that permutes
///         the rows and columns of the system alike into Eigen's minimum degree order
///         (`Eigen::AMDOrdering`) of its pattern and prefers the diagonal as pivot: the map of
///         `Eigen::SparseLU` with its own column ordering (COLAMD), with less fill, so faster on
///         large meshes (the benchmark, built without SuiteSparse, says by how much);
///         or, when CGAL's macro `CGAL_SMP_USE_SPARSESUITE_SOLVERS` is defined (as for CGAL's
///         ARAP and Orbifold Tutte parameterizers; the package's CMake target defines it if
///         SuiteSparse's UMFPACK is found; link UMFPACK), faster here (the benchmark says by how
///         much), an internal wrapper of UMFPACK's LU, used with
///         AMD ordering below 150,000 unknowns and METIS above, without UMFPACK's iterative
///         refinement, and frugal with memory: its work area is sized from the symbolic analysis
///         and then from the previous factorization, and its factors are freed as soon as they
///         have served (the benchmark measures the peak memory of a call).
///         Translation units built with and without the macro get distinct types (an inline
///         namespace per configuration), never two definitions of one.
///         With the macro, a `Eigen::UmfPackLU` given here is ordered and run without refinement
///         the same way.
///         With the default traits, systems of 30,000 unknowns or more are solved instead by
///         an internal multigrid solver (BiCGSTAB preconditioned by a smoothed aggregation
///         algebraic multigrid cycle, started from the previous step's map, to a residual of
///         \f$ 10^{-12} \f$ times the right-hand side's), whose time and memory grow in
///         proportion to the mesh where those of a sparse LU grow faster: the stretch of every
///         step is the direct solver's to about \f$ 10^{-6} \f$ (tested). After \f$ U^0 \f$,
///         a step is first solved to a residual of \f$ 10^{-6} \f$ only: a map whose stretch is
///         then more than 1% above the kept one's is rejected as it is (the paper's last step, so
///         marked in the report: `Stretch_minimizing_step::screened`), the others are solved on
///         to \f$ 10^{-12} \f$ by the same iteration (the same maps). It gives way to the
///         direct solver for the rest of the call if it does not converge, or if its map has a
///         flipped face. Solver traits given here are used at every size.
///         Symmetric weights (the clamped cotangent start with the edge or symmetric update, as
///         `Stretch_minimizing_preset::LOWEST_STRETCH` sets) make the system symmetric positive
///         definite: a direct Eigen solver given here then gives way to a sparse Cholesky
///         (Eigen's `SimplicialLDLT`, in METIS's order of the vertices on large meshes when the
///         package's macro `CGAL_SMP_USE_CHOLMOD` is defined), but for UMFPACK on large systems
///         without CHOLMOD; the map is the same to rounding.
///
/// \sa `CGAL::Surface_mesh_parameterization::Shape_preserving_parameterizer_3`
/// \sa `CGAL::Surface_mesh_parameterization::Stretch_minimizing_report`
template <class TriangleMesh_,
          class InitialParameterizer_ = Default,
          class SolverTraits_ = Default>
class Stretch_minimizing_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                       Triangle_mesh;
  /// Triangle mesh type (the spelling of CGAL's parameterizers)
  typedef TriangleMesh_                                       TriangleMesh;

#ifndef DOXYGEN_RUNNING
  typedef typename Default::Get<
    InitialParameterizer_,
    Shape_preserving_parameterizer_3<TriangleMesh_,
                                     Square_border_arc_length_parameterizer_3<TriangleMesh_> > >::type
                                                              Initial_parameterizer;
  typedef typename Default::Get<SolverTraits_, internal::Default_solver_traits>::type
                                                              Solver_traits;
#else
  /// Initial parameterizer type
  typedef InitialParameterizer_                               Initial_parameterizer;
  /// Solver traits type
  typedef SolverTraits_                                       Solver_traits;
#endif

  /// Border parameterizer type, the one of the initial parameterizer
  typedef typename Initial_parameterizer::Border_parameterizer Border_parameterizer;

  /// Mesh vertex type
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor   vertex_descriptor;
  /// Mesh halfedge type
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

  /// Default cap on the number of reweighting steps (the named parameter `number_of_iterations`).
  static constexpr unsigned int default_number_of_iterations = internal::default_max_iterations;

  /// Builds the paper's method: \f$ \eta = 1 \f$, stop when the stretch increases, at most
  /// `default_number_of_iterations` steps.
  /// \param initializer the parameterizer that gives the border and the weights of \f$ U^0 \f$
  /// \param solver_traits the sparse solver
  explicit Stretch_minimizing_parameterizer_3(const Initial_parameterizer& initializer = Initial_parameterizer(),
                                              const Solver_traits& solver_traits = Solver_traits())
    : m_initializer(initializer), m_solver_traits(solver_traits),
      m_report(std::make_shared<internal::Shared_report<Stretch_minimizing_report> >()),
      m_solver_mutex(std::make_shared<std::mutex>())
  { }

  /// Builds the method with options, from a default-constructed initial parameterizer.
  ///
  /// \param np a sequence of named parameters among the ones listed below, e.g.
  ///        `SMP::parameters::eta(0.5).number_of_iterations(10)`
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{preset}
  ///     \cgalParamDescription{a set of the options below with a name; options given beside it override it}
  ///     \cgalParamType{`Stretch_minimizing_preset`}
  ///     \cgalParamDefault{`Stretch_minimizing_preset::PAPER`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{eta}
  ///     \cgalParamDescription{exponent of the weight update \f$ w_{ij} \leftarrow w_{ij} / \sigma_j^{\eta} \f$;
  ///                           smaller values take smaller, steadier steps}
  ///     \cgalParamType{double in \f$ (0, 1] \f$ (`SMP::parameters::eta()`)}
  ///     \cgalParamDefault{1, as in the paper}
  ///     \cgalParamExtra{a value outside \f$ (0, 1] \f$ makes `parameterize()` return `ERROR_WRONG_PARAMETER`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_iterations}
  ///     \cgalParamDescription{cap on the number of solves after \f$ U^0 \f$: 0 gives \f$ U^0 \f$, 1 gives \f$ U^1 \f$}
  ///     \cgalParamType{unsigned int}
  ///     \cgalParamDefault{20 (`default_number_of_iterations`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{start_weights}
  ///     \cgalParamDescription{the weights of \f$ U^0 \f$}
  ///     \cgalParamType{`Start_weights`}
  ///     \cgalParamDefault{`Start_weights::INITIALIZER`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{stretch_update}
  ///     \cgalParamDescription{the stretch that divides each weight at each step}
  ///     \cgalParamType{`Stretch_update`}
  ///     \cgalParamDefault{`Stretch_update::VERTEX`, as in the paper}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{step_rule}
  ///     \cgalParamDescription{what to do when a step does not decrease the stretch}
  ///     \cgalParamType{`Step_rule`}
  ///     \cgalParamDefault{`Step_rule::STOP_AT_INCREASE`, as in the paper}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{descent_iterations}
  ///     \cgalParamDescription{after \f$ U^{opt} \f$, descent steps of Sander's L2 stretch energy, flip-free
  ///                           by construction of the line search, at most this many: projected Newton steps
  ///                           without the terms of the Hessian that couple u and v (two systems the size of
  ///                           the mesh, factored side by side: about a quarter of the flops of a Newton step)
  ///                           while the last three steps lower the energy by 0.2% or more a step on average
  ///                           (one step cut short by a fold does not end them); with `free_border(true)`, steps
  ///                           along its gradient preconditioned by the cotangent Laplacian of the mesh
  ///                           (factored once: a step costs far less than a reweighting step), until they
  ///                           converge (0: none)}
  ///     \cgalParamType{unsigned int}
  ///     \cgalParamDefault{0 (`Stretch_minimizing_preset::LOWEST_STRETCH`: see there)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{polish_iterations}
  ///     \cgalParamDescription{after \f$ U^{opt} \f$ and the descent steps, at most this many iterations of a
  ///                           projected Newton descent of Sander's L2 stretch energy (a factorization each),
  ///                           flip-free by construction of its line search (0: none)}
  ///     \cgalParamType{unsigned int}
  ///     \cgalParamDefault{0}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{polish_time_budget}
  ///     \cgalParamDescription{time budget of the polish (descent and Newton steps), in seconds (0: none);
  ///                           without `polish_iterations`, it asks for Newton steps with no cap}
  ///     \cgalParamType{double}
  ///     \cgalParamDefault{0}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{free_border}
  ///     \cgalParamDescription{if `true`, the polish moves the border vertices too, and never lets the border
  ///                           cross itself; the result is scaled into the unit square}
  ///     \cgalParamType{bool}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_threads}
  ///     \cgalParamDescription{threads for the stretch evaluation, the weight update, the filling of
  ///                           the matrix and the solves for \f$ s \f$ and \f$ t \f$ (with UMFPACK), on meshes
  ///                           large enough to gain from them; 0 takes one per core. The result does not
  ///                           depend on it, bit for bit.}
  ///     \cgalParamType{unsigned int}
  ///     \cgalParamDefault{0}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{verbose}
  ///     \cgalParamDescription{if `true`, one line per step is written to `std::cerr`}
  ///     \cgalParamType{bool}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{visitor}
  ///     \cgalParamDescription{called after every solve with a `const Stretch_minimizing_step&`;
  ///                           if it returns `false`, the iteration stops (the best step so far is kept).
  ///                           It is copied: pass `std::ref(v)` to keep its state in `v`.}
  ///     \cgalParamType{a callable returning `bool` or `void`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <typename T, typename Tag, typename Base>
  explicit Stretch_minimizing_parameterizer_3(const Named_function_parameters<T, Tag, Base>& np)
    : Stretch_minimizing_parameterizer_3(Initial_parameterizer(), np)
  { }

  /// Builds the method from an initializer and options.
  /// \param initializer the parameterizer that gives the border and the weights of \f$ U^0 \f$
  /// \param np a sequence of named parameters, the ones of the constructor above
  /// \param solver_traits the sparse solver
  template <typename T, typename Tag, typename Base>
  Stretch_minimizing_parameterizer_3(const Initial_parameterizer& initializer,
                                     const Named_function_parameters<T, Tag, Base>& np,
                                     const Solver_traits& solver_traits = Solver_traits())
    : Stretch_minimizing_parameterizer_3(initializer, solver_traits)
  {
    m_settings = internal::read_settings(np, m_settings);
  }

  /// Computes \f$ U^{opt} \f$ of the connected component of `bhd` and writes it to `uvmap`.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and a 2D point as value
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `int` as value
  ///         (passed on to the border parameterizer; this class numbers vertices itself)
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `bool` as value
  ///
  /// \param mesh the triangle mesh; only the component of `bhd` is read, and the mesh is not modified
  ///        (a temporary vertex property may be added and removed)
  /// \param bhd a halfedge on the border of that component
  /// \param uvmap receives the parameterization of the vertices of that component (on success)
  /// \param vimap vertex index map
  /// \param vpmap receives `true` for every parameterized vertex
  /// \param np an optional sequence of named parameters (see below)
  ///
  /// The named parameters are the ones of the constructor (`preset`, `eta`, `number_of_iterations`,
  /// `start_weights`, `stretch_update`, `step_rule`, `descent_iterations`, `polish_iterations`, `polish_time_budget`,
  /// `free_border`, `number_of_threads`, `verbose`, `visitor`); each one given overrides, for this call only, the value
  /// given to the constructor (a preset resets the options of the constructor that it sets).
  ///
  /// \pre `uvmap`, `vimap` and `vpmap` hold an entry for every vertex of the component of `bhd`
  ///      (as `CGAL::Surface_mesh_parameterization::parameterize()` provides). Everything else
  ///      is checked: bad input gives an error code below, never undefined behaviour.
  ///
  /// \returns `OK`, or:
  /// - `ERROR_WRONG_PARAMETER`: `eta` outside \f$ (0, 1] \f$, `bhd` not a border halfedge, or
  ///   a non-finite vertex coordinate;
  /// - `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NO_TOPOLOGICAL_DISC` (no border,
  ///   handles, a boundary that touches itself or another one at a vertex);
  /// - the error of the border parameterizer (e.g. `ERROR_BORDER_TOO_SHORT`);
  /// - `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`: initial weights not finite and positive (zero-length
  ///   edges), the solver failed on \f$ U^0 \f$ (a later failure keeps the best map so far:
  ///   `Stretch_minimizing_stop::SOLVER_FAILED`), or memory ran out (`std::bad_alloc`, caught);
  /// - `ERROR_NO_1_TO_1_MAPPING`: already \f$ U^0 \f$ has flipped faces (non-convex border).
  ///
  /// `report().message` says more. On an error, no interior vertex is written (the border
  /// parameterizer may already have written the border).
  ///
  /// A null `bhd` gets an error code here, and through the free function
  /// `CGAL::Surface_mesh_parameterization::parameterize()` of this class (below) too.
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap,
            typename NamedParameters = parameters::Default_named_parameters>
  Error_code parameterize(Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap vimap,
                          VertexParameterizedMap vpmap,
                          const NamedParameters& np = parameters::default_values())
  {
    return run(mesh, bhd, uvmap, vimap, vpmap, internal::read_settings(np, m_settings));
  }

  /// The outcome of the last call of `parameterize()` to end on this object or a copy of it
  /// (`CGAL::Surface_mesh_parameterization::parameterize()` calls a copy).
  Stretch_minimizing_report report() const { return m_report->read(); }

  /// The exponent \f$ \eta \f$ given to the constructor.
  double eta() const { return m_settings.eta; }

  /// The cap on the number of steps given to the constructor.
  unsigned int number_of_iterations() const { return m_settings.max_iterations; }

  /// The parameterizer that gives the border and the weights of \f$ U^0 \f$.
  Initial_parameterizer& initial_parameterizer() { return m_initializer; }

private:
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code run(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                 VertexIndexMap vimap, VertexParameterizedMap vpmap,
                 const internal::Stretch_minimizing_settings& settings)
  {
    Stretch_minimizing_report rep;
    Error_code status;
    {
      // copies share the solver (CGAL's Eigen_solver_traits holds it by a shared pointer)
      std::lock_guard<std::mutex> lock(*m_solver_mutex);
      try {
        status = run(mesh, bhd, uvmap, vimap, vpmap, settings, rep);
      } catch(const std::bad_alloc&) {
        internal::release_factors_of(m_solver_traits);
        status = rep.status = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
        rep.message = "out of memory (std::bad_alloc): the mesh is too large for the memory available";
      }
    }
    m_report->publish(std::move(rep));
    return status;
  }

  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code run(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                 VertexIndexMap vimap, VertexParameterizedMap vpmap,
                 const internal::Stretch_minimizing_settings& settings, Stretch_minimizing_report& rep)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    const auto start = std::chrono::steady_clock::now();
    auto fail = [&rep](Error_code e, const std::string& why) {
      rep.status = e;
      rep.message = why;
      return e;
    };

    if(!(settings.eta > 0. && settings.eta <= 1.))
      return fail(ERROR_WRONG_PARAMETER, "eta must be in (0, 1]");

    internal::Disk_component<Triangle_mesh> dc;
    Error_code status = dc.build(mesh, bhd, get(vertex_point, mesh));
    if(status != OK)
      return fail(status, dc.message);
    rep.interior_vertices = dc.number_of_rows();
    rep.border_vertices = dc.border.size();
    rep.faces = dc.flat.tri.size();
    rep.holes_closed = dc.holes;

    // CGAL's square border finds its corners through vpmap: entries left true by an earlier
    // call would move them
    for(vertex_descriptor v : dc.vertices)
      put(vpmap, v, false);
    status = m_initializer.get_border_parameterizer().parameterize(mesh, bhd, uvmap, vimap, vpmap);
    if(status != OK)
      return fail(status, std::string("the border parameterizer failed: ") + error_message(status));
    std::vector<internal::Vec2> uv(dc.flat.xyz.size(), internal::Vec2{0., 0.}); // with hole centers
    for(int v : dc.border) {
      const Point_2 p = get(uvmap, dc.vertices[v]);
      uv[v] = {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
      if(!std::isfinite(uv[v][0]) || !std::isfinite(uv[v][1]))
        return fail(ERROR_WRONG_PARAMETER, "the border parameterizer gave a non-finite position");
    }

    std::vector<double> w;
    bool symmetric = false;
    if(!initial_weights(mesh, dc, settings.start, w, symmetric))
      return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM,
                  "the initial weights of an interior vertex are not finite and positive "
                  "(degenerate faces, e.g. zero-length edges, around it)");

    std::vector<internal::Vec2> best_uv;
    // the vertex update scales the columns of the weights: only the others keep them symmetric
    symmetric = symmetric && settings.update != Stretch_update::VERTEX;
    // one elimination order of the vertices for all the Cholesky factorizations of this call of
    // one row per vertex (the symmetric reweighting systems, the descent's systems)
    typedef internal::Weighted_laplacian_system<Solver_traits> System;
    const std::vector<int> rank = (symmetric && System::cholesky_possible) || settings.descent_iterations > 0
                                    ? internal::fill_reducing_vertex_rank(dc.flat.xyz.size(), dc.flat.tri, dc.virtual_tri)
                                    : std::vector<int>();
    const bool solved = iterate(dc, settings, start, symmetric, rank, w, uv, best_uv, rep);
    internal::release_factors_of(m_solver_traits);
    if(!solved)
      return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "the sparse solver failed");
    if(best_uv.empty())
      return fail(ERROR_NO_1_TO_1_MAPPING, "the initial parameterization has flipped faces");
    if(settings.polish())
      internal::polish_stage(dc, dc.vertices.size(), rank, settings, start, best_uv, rep.polish);
    for(std::size_t v = 0; v < dc.vertices.size(); ++v) {
      put(uvmap, dc.vertices[v], Point_2(best_uv[v][0], best_uv[v][1]));
      put(vpmap, dc.vertices[v], true);
    }
    rep.status = OK;
    return OK;
  }

  // Solves, measures and reweights until the rule of `settings` stops; `best_uv` receives the
  // best flip-free parameterization (empty if U^0 has flipped faces). False if a solve fails.
  // `symmetric`: the weights are and stay symmetric; `rank`: the elimination order of the vertices.
  bool iterate(const internal::Disk_component<Triangle_mesh>& dc,
               const internal::Stretch_minimizing_settings& settings,
               std::chrono::steady_clock::time_point start, bool symmetric, const std::vector<int>& rank,
               std::vector<double>& w, std::vector<internal::Vec2>& uv,
               std::vector<internal::Vec2>& best_uv, Stretch_minimizing_report& rep)
  {
    internal::Weighted_laplacian_system<Solver_traits> system(dc, symmetric, rank);
    internal::Flat_stretch stretch;
    internal::Stretch_update_ratios ratios;
    ratios.init(settings.update, dc);
    std::vector<double> w_kept; // the weights of the kept step, to step again from it (HALVE_ETA)
    const bool halving = settings.rule == Step_rule::HALVE_ETA;
    internal::Stopping_rule stop_rule;
    stop_rule.rule = settings.rule;
    // two halvings: further ones changed the stretch in the fourth digit at most, on the
    // bundled meshes and CGAL's sample meshes, for two more solves each time
    stop_rule.eta_floor = settings.eta / 4.;
    stop_rule.max_iterations = settings.max_iterations;
    double eta = settings.eta;
    const unsigned int threads = internal::thread_count(settings.threads);
    for(std::size_t h = 0;; ++h) {
      stretch.release();
      // after a step is kept, the multigrid solver first solves only far enough to tell a step
      // that clearly raises the stretch (the paper's last step, rejected): such a step needs no
      // more; the others are solved fully
      bool solved = system.solve(w, uv, m_solver_traits, threads, !best_uv.empty());
      internal::Flat_stretch_summary s;
      if(solved)
        s = stretch.evaluate(dc.flat, uv, threads);
      const bool screened_out = solved && system.screened() && s.flipped == 0 &&
                                internal::Stopping_rule::clearly_raises(s.l2, rep.history[rep.kept_step].l2_stretch);
      if(solved && system.screened() && !screened_out) {
        solved = system.refine(w, uv, m_solver_traits, threads);
        if(solved)
          s = stretch.evaluate(dc.flat, uv, threads);
      }
      if(solved && s.flipped > 0 && system.multigrid()) {
        // the flip may be the error of the multigrid solution, exact only up to a tolerance:
        // the direct solver settles it, for this step and the next ones
        system.use_direct_solver();
        solved = system.solve(w, uv, m_solver_traits, threads);
        if(solved)
          s = stretch.evaluate(dc.flat, uv, threads);
      }
      if(!solved) {
        if(best_uv.empty())
          return false;
        rep.stop = Stretch_minimizing_stop::SOLVER_FAILED;
        rep.message = "the sparse solver failed at step " + std::to_string(h) + ": the best map so far is kept";
        return true;
      }

      Stretch_minimizing_step step = internal::make_step(h, s, start);
      step.eta = h == 0 ? 0. : eta;
      step.solver_iterations = system.solver_iterations();
      step.screened = screened_out;
      rep.history.push_back(step);
      rep.degenerate_3d_faces = s.degenerate_3d;
      if(settings.verbose)
        std::cerr << "stretch minimization: step " << h << "  eta " << step.eta << "  L2 " << s.l2
                  << "  Linf " << s.linf << "  flipped " << s.flipped << "  degenerate "
                  << s.degenerate_uv << "  solver iterations " << step.solver_iterations
                  << (step.screened ? " (screened)" : "") << "  " << step.seconds << " s"
                  << std::endl;

      const bool valid = s.flipped == 0 && std::isfinite(s.l2) && s.l2 > 0.;
      const bool better = valid && (best_uv.empty() ||
                                    internal::Stopping_rule::lowers(s.l2, rep.history[rep.kept_step].l2_stretch));
      if(better) {
        rep.kept_step = h;
        best_uv = uv;
        if(halving)
          w_kept = w;
      }
      const bool go_on = settings.visitor ? settings.visitor(step) : true;
      rep.stop = stop_rule(h, valid, better, !best_uv.empty(), eta, go_on);
      if(rep.stop != Stretch_minimizing_stop::NOT_RUN)
        return true;

      if(better) {
        ratios.update(dc, stretch, s.rms, eta, w, w, threads);
      } else {
        // a rejected step is taken again from the kept one, half as long
        eta /= 2.;
        s = stretch.evaluate(dc.flat, best_uv, threads);
        ratios.update(dc, stretch, s.rms, eta, w_kept, w, threads);
      }
    }
  }

  // w^0 in the ring order of `dc`: the initializer's, or computed on the flat rings; around a
  // closed hole, where the initializer cannot see the virtual faces, always on the flat ring
  // (shape-preserving weights, unless other start weights are asked for). `symmetric` tells
  // whether w_ij = w_ji between interior vertices.
  bool initial_weights(const Triangle_mesh& mesh, const internal::Disk_component<Triangle_mesh>& dc,
                       Start_weights kind, std::vector<double>& w, bool& symmetric)
  {
    symmetric = false;
    if(kind == Start_weights::CLAMPED_COTANGENT)
      return internal::clamped_cotangent_weights(dc, w, symmetric);
    w.resize(dc.ring.size());
    internal::Shape_preserving_ring_weights floater;
    std::vector<internal::Vec3> ring;
    std::vector<double> ring_w;
    for(std::size_t r = 0; r < dc.number_of_rows(); ++r) {
      const int first = dc.ring_begin[r], last = dc.ring_begin[r + 1];
      if(dc.flat_ring[r] || kind != Start_weights::INITIALIZER) {
        ring.clear();
        for(int e = first; e < last; ++e)
          ring.push_back(dc.flat.xyz[dc.ring[e]]);
        const internal::Vec3& center = dc.flat.xyz[dc.interior[r]];
        const bool ok = kind == Start_weights::MEAN_VALUE ? internal::mean_value_ring_weights(center, ring, ring_w)
                                                          : floater.compute(center, ring, ring_w);
        if(!ok)
          return false;
        std::copy(ring_w.begin(), ring_w.end(), w.begin() + first);
        continue;
      }
      const vertex_descriptor v = dc.vertices[dc.interior[r]];
      int e = first;
      double sum = 0.;
      Vertex_around_target_circulator<Triangle_mesh> vj(halfedge(v, mesh), mesh), end = vj;
      CGAL_For_all(vj, end) {
        if(e == last)
          return false;
        const double wij = CGAL::to_double(m_initializer.compute_w_ij(mesh, v, vj));
        if(!(wij >= 0.) || !std::isfinite(wij))
          return false;
        w[e++] = wij;
        sum += wij;
      }
      if(e != last || !(sum > 0.))
        return false;
    }
    return true;
  }

  internal::Exposed_initializer<Initial_parameterizer> m_initializer;
  Solver_traits m_solver_traits;
  internal::Stretch_minimizing_settings m_settings;
  std::shared_ptr<internal::Shared_report<Stretch_minimizing_report> > m_report; // shared by copies, see the class comment
  std::shared_ptr<std::mutex> m_solver_mutex; // held by a call: copies share m_solver_traits' solver
};

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// CGAL's free function `CGAL::Surface_mesh_parameterization::parameterize(mesh, parameterizer, bhd, uvmap)`
/// for this class: overload resolution picks it when that function is called as CGAL's manual
/// shows, with the same arguments and result. It numbers the vertices of the component of `bhd`
/// by a walk over its faces, where CGAL's function finds the component with
/// `CGAL::Polygon_mesh_processing::connected_component()`, whose `std::set` of faces takes much
/// of the time of a call on meshes of millions of faces; and a null or inner `bhd` gets an error
/// code (see `Stretch_minimizing_parameterizer_3::parameterize()`), where CGAL's function has a
/// precondition.
///
/// \param mesh the triangle mesh
/// \param parameterizer the parameterizer (copied, as by CGAL's function: its `report()` is shared)
/// \param bhd a halfedge on the border of the component to parameterize
/// \param uvmap receives the parameterization of the vertices of that component
template <class TriangleMesh, class InitialParameterizer, class SolverTraits, class HD, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Stretch_minimizing_parameterizer_3<TriangleMesh, InitialParameterizer, SolverTraits> parameterizer,
                        HD bhd,
                        VertexUVmap uvmap)
{
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  internal::number_component_vertices(bhd, mesh, vimap);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  return parameterizer.parameterize(mesh, bhd, uvmap, vimap, vpmap);
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_PARAMETERIZER_3_H
