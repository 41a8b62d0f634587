// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What solver_configuration_eigen.cpp, built without SuiteSparse, offers the other translation
// units of its test: no type of the package crosses.

#ifndef SMP_TEST_SOLVER_CONFIGURATION_EIGEN_H
#define SMP_TEST_SOLVER_CONFIGURATION_EIGEN_H

#include <string>

// typeid name of the default `Stretch_minimizing_parameterizer_3<Surface_mesh>` there
const char* eigen_configuration_type_name();

// L2 stretch of U^opt of the mesh in `file` by the default parameterizer there; -1 on failure
double eigen_configuration_stretch(const std::string& file);

#endif
