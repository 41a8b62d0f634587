// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A second translation unit of test_stretch_minimizing, built without SuiteSparse whatever the
// others use: the package's entities must be other types here when the configurations differ
// (solver_configuration.h), so that the two coexist in one program.

#undef CGAL_SMP_USE_SPARSESUITE_SOLVERS
#undef CGAL_SMP_USE_CHOLMOD

#include "solver_configuration_eigen.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <fstream>
#include <typeinfo>

namespace {
typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
typedef CGAL::Simple_cartesian<double>::Point_2 Point_2;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
} // namespace

const char* eigen_configuration_type_name()
{
  return typeid(SMP::Stretch_minimizing_parameterizer_3<Mesh>).name();
}

double eigen_configuration_stretch(const std::string& file)
{
  Mesh m;
  std::ifstream in(file);
  if(!(in >> m))
    return -1.;
  auto uv = m.add_property_map<Mesh::Vertex_index, Point_2>("v:uv").first;
  SMP::Stretch_minimizing_parameterizer_3<Mesh> p;
  if(SMP::parameterize(m, p, CGAL::Polygon_mesh_processing::longest_border(m).first, uv) != SMP::OK)
    return -1.;
  return p.report().l2_stretch();
}
