// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_EXPOSED_INITIALIZER_H
#define CGAL_SMP_INTERNAL_EXPOSED_INITIALIZER_H

#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_report.h>

#include <CGAL/Named_function_parameters.h>

#include <functional>
#include <type_traits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A fixed-border parameterizer keeps its weights (`compute_w_ij`) and its border
// parameterizer protected; the stretch minimizer reuses both, so it holds the initializer
// through this derived class, which makes them public.
template <typename Initializer>
class Exposed_initializer : public Initializer
{
public:
  explicit Exposed_initializer(const Initializer& init) : Initializer(init) { }
  using Initializer::compute_w_ij;
  using Initializer::get_border_parameterizer;
};

typedef std::function<bool(const Stretch_minimizing_step&)> Step_visitor;

// Wraps a user visitor: a callable taking `const Stretch_minimizing_step&` and returning
// `bool` (false: stop) or nothing.
template <typename Visitor>
Step_visitor make_step_visitor(const Visitor& v)
{
  if constexpr(std::is_same<Visitor, CGAL::internal_np::Param_not_found>::value) {
    return Step_visitor();
  } else if constexpr(std::is_invocable_r<bool, Visitor, const Stretch_minimizing_step&>::value
                      && !std::is_void<std::invoke_result_t<Visitor, const Stretch_minimizing_step&> >::value) {
    return Step_visitor(v);
  } else {
    static_assert(std::is_invocable<Visitor, const Stretch_minimizing_step&>::value,
                  "the visitor must be callable with a const Stretch_minimizing_step&");
    return [v](const Stretch_minimizing_step& s) mutable { std::invoke(v, s); return true; };
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_EXPOSED_INITIALIZER_H
