// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_STRETCH_MINIMIZING_SETTINGS_H
#define CGAL_SMP_INTERNAL_STRETCH_MINIMIZING_SETTINGS_H

#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Exposed_initializer.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_named_parameters.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The cap on the reweighting steps when `number_of_iterations` is not given.
constexpr unsigned int default_max_iterations = 20;

// Every option of the stretch minimizer, as read from named parameters.
struct Stretch_minimizing_settings
{
  double eta = 1.;
  unsigned int max_iterations = default_max_iterations;
  Start_weights start = Start_weights::INITIALIZER;
  Stretch_update update = Stretch_update::VERTEX;
  Step_rule rule = Step_rule::STOP_AT_INCREASE;
  unsigned int descent_iterations = 0;
  unsigned int polish_iterations = 0;
  double polish_seconds = 0.;
  bool free_border = false;
  unsigned int threads = 0; // 0: one per core
  bool verbose = false;
  Step_visitor visitor;

  // a time budget alone asks for the polish too, with no cap on its steps
  bool polish() const { return descent_iterations > 0 || polish_iterations > 0 || polish_seconds > 0.; }

  void apply(Stretch_minimizing_preset p)
  {
    eta = 1.;
    rule = Step_rule::STOP_AT_INCREASE;
    if(p == Stretch_minimizing_preset::LOWEST_STRETCH) {
      start = Start_weights::CLAMPED_COTANGENT;
      update = Stretch_update::EDGE;
      descent_iterations = lowest_stretch_descent_iterations;
    } else {
      start = Start_weights::INITIALIZER;
      update = Stretch_update::VERTEX;
      descent_iterations = 0;
    }
  }
};

// `base` with the options of `np` applied: a preset first, then every option given.
template <typename NamedParameters>
Stretch_minimizing_settings read_settings(const NamedParameters& np, Stretch_minimizing_settings s)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::preset_t>::value)
    s.apply(get_parameter(np, internal_np::preset));
  s.eta = choose_parameter(get_parameter(np, internal_np::eta), s.eta);
  s.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), s.max_iterations);
  s.start = choose_parameter(get_parameter(np, internal_np::start_weights), s.start);
  s.update = choose_parameter(get_parameter(np, internal_np::stretch_update), s.update);
  s.rule = choose_parameter(get_parameter(np, internal_np::step_rule), s.rule);
  s.descent_iterations = choose_parameter(get_parameter(np, internal_np::descent_iterations), s.descent_iterations);
  s.polish_iterations = choose_parameter(get_parameter(np, internal_np::polish_iterations), s.polish_iterations);
  s.polish_seconds = choose_parameter(get_parameter(np, internal_np::polish_time_budget), s.polish_seconds);
  s.free_border = choose_parameter(get_parameter(np, internal_np::free_border), s.free_border);
  s.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), s.threads);
  s.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), s.verbose);
  Step_visitor v = make_step_visitor(get_parameter(np, CGAL::internal_np::visitor));
  if(v)
    s.visitor = v;
  return s;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_STRETCH_MINIMIZING_SETTINGS_H
