// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_STOPPING_RULE_H
#define CGAL_SMP_INTERNAL_STOPPING_RULE_H

// The paper's stopping rule (Yoshizawa, Belyaev and Seidel 2004): the reweighting goes on while
// the normalized L2 stretch decreases, and U^opt is the last step that lowered it. With
// Step_rule::HALVE_ETA a step that does not lower it is taken again from U^opt with half the
// eta, until eta would fall below a floor. The iteration cap and the visitor come after it.

#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_options.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_report.h>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

struct Stopping_rule
{
  Step_rule rule = Step_rule::STOP_AT_INCREASE;
  double eta_floor = 0.;          // HALVE_ETA: the smallest eta tried
  std::size_t max_iterations = 0; // reweighting steps

  // Whether a step of stretch `l2` lowers the kept `kept_l2`: a decrease at the level of
  // rounding is no decrease (it would only prolong the iteration).
  static bool lowers(double l2, double kept_l2) { return l2 < kept_l2 * (1. - 1e-10); }

  // Whether a step whose map was solved only approximately, with stretch `l2`, surely does not
  // lower the kept `kept_l2`: it raises it by more than the error of that stretch can be (a
  // hundredfold margin over the largest error measured, see test_stretch_minimizing).
  static bool clearly_raises(double l2, double kept_l2) { return l2 > kept_l2 * (1. + screening_margin); }
  static constexpr double screening_margin = 1e-2;

  // Why the iteration stops after step h, or NOT_RUN to go on. `valid`: step h has no flipped
  // face and a finite stretch; `better`: it is valid and lowers the kept stretch (or is the
  // first valid step); `kept`: a valid step is kept; `eta`: the eta of step h; `go_on`: the
  // visitor's answer.
  Stretch_minimizing_stop operator()(std::size_t h, bool valid, bool better, bool kept, double eta, bool go_on) const
  {
    if(!kept)
      return Stretch_minimizing_stop::FLIPPED_FACES;
    if(!better && (rule != Step_rule::HALVE_ETA || eta / 2. < eta_floor))
      return valid ? Stretch_minimizing_stop::STRETCH_INCREASED : Stretch_minimizing_stop::FLIPPED_FACES;
    if(h >= max_iterations)
      return Stretch_minimizing_stop::ITERATION_CAP;
    if(!go_on)
      return Stretch_minimizing_stop::VISITOR;
    return Stretch_minimizing_stop::NOT_RUN;
  }
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_STOPPING_RULE_H
