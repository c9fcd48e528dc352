/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestProperties.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestProperties.h
 * @brief Volume properties of the vtkHAVS tests (no OpenGL: the core tests use them too).
 */
#ifndef havsTestProperties_h
#define havsTestProperties_h

#include "vtkSmartPointer.h"

class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace havstest
{
/// A property with the given constant colour and opacity.
vtkSmartPointer<vtkVolumeProperty> MakeConstantProperty(
  double r, double g, double b, double opacity, double unitDistance);

/// A property ramping opacity and colour over [lo, hi] (not empty, not
/// opaque); every opacity node is a colour node too.
vtkSmartPointer<vtkVolumeProperty> MakeRampProperty(
  double lo, double hi, double maxOpacity, double unitDistance);

/// MakeRampProperty over the grid's scalar range, opacity 0.8 at the top,
/// unit distance an eighth of the bounds' diagonal.
vtkSmartPointer<vtkVolumeProperty> MakeRampPropertyFor(vtkUnstructuredGrid* grid);

/// havs_benchmark's default transfer function over the grid's scalar range
/// (the colour nodes of MakeRampProperty; opacity 0, 0.1 at 30 %, 0.8 at the
/// top; unit distance an eighth of the diagonal): for scenes found there.
vtkSmartPointer<vtkVolumeProperty> MakeBenchmarkPropertyFor(vtkUnstructuredGrid* grid);

}

#endif
