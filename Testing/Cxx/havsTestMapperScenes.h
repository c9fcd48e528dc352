/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestMapperScenes.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestMapperScenes.h
 * @brief The exact reference, and the scenes every exact mapper of the
 * project draws alike (the cell projection's and the ray caster's tests),
 * each mapper driven through vtkHAVSMapperBase.
 */
#ifndef havsTestMapperScenes_h
#define havsTestMapperScenes_h

#include "havsTestImages.h" // For ImageDifference

#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkType.h"         // For vtkIdType

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkCamera;
class vtkFloatArray;
class vtkHAVSMapperBase;
class vtkHAVSReferenceRenderer;
class vtkPlaneCollection;
class vtkRenderer;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace havstest
{
/// A new mapper of the project's by the name the tests' arguments use:
/// "raycast", "cellprojection", anything else HAVS.
vtkSmartPointer<vtkHAVSMapperBase> MakeMapperNamed(const std::string& name);

/// A vtkHAVSReferenceRenderer of `grid` with `property`, `camera`, size x
/// size (for a test that sets more before Render()).
vtkSmartPointer<vtkHAVSReferenceRenderer> MakeReference(
  vtkUnstructuredGrid* grid, vtkVolumeProperty* property, vtkCamera* camera, int size);

/// The exact image of vtkHAVSReferenceRenderer, size x size RGBA (clipped by
/// `planes`, cut at the window depth `depth`, when given; under `blend`,
/// vtkVolumeMapper's numbering; the property's isosurfaces inside the
/// composite volume with `isoInComposite`); `startedInside` gets its rays
/// that start in the mesh.
std::vector<float> ReferenceImage(vtkUnstructuredGrid* grid, vtkVolumeProperty* property,
  vtkCamera* camera, int size, vtkPlaneCollection* planes = nullptr, vtkFloatArray* depth = nullptr,
  int blend = 0, vtkIdType* startedInside = nullptr, bool isoInComposite = false);

/// The bound an exact mapper meets against ReferenceImage: RMSE < 5e-4 and
/// max < 0.01 (float images, edge pixels left out by the comparison).
bool WithinExactBound(const ImageDifference& d);

/// One line: what, RMSE, max and the pixels over 1/255.
void PrintDifference(const std::string& what, const ImageDifference& d);

/// The views the exact mappers' scenes go through: view v < views is the
/// standard view v (vtkHAVSStandardViews; turned 7 degrees in azimuth and 5
/// in elevation off the axes when `turned`), v == views a parallel view of
/// standard view 3, turned so and then 11 and 7 degrees more.
void PlaceStandardView(
  vtkRenderer* renderer, vtkUnstructuredGrid* grid, int v, int views, bool turned);

/// Clipping planes on the hollow sphere: one and two planes, perspective and
/// parallel (`all`; otherwise one plane in perspective, two in parallel),
/// against the reference clipped alike. Control: the mapper without the
/// planes against the clipped reference must be off by more than 0.05.
int ClipPlanesScene(vtkHAVSMapperBase* mapper, int size, bool all);

/// An opaque sphere inside a box: the rays end at its surface (against the
/// reference cut at the window's depth). Control: the reference through the
/// surface must fail.
int OpaqueSphereScene(vtkHAVSMapperBase* mapper, int size);

/**
 * The camera inside the mesh ("box" or a data set, PlaceCameraInside:
 * perspective, the near plane in the mesh) under the four blends (composite,
 * maximum, minimum, additive) against the reference, which starts the rays at
 * the near plane. `afterFrame` (when given) runs after each blend's frame
 * (the ray caster prints its counts). Control: without the near plane's
 * section the image must fail (the maximum's control is printed only: its
 * maximum lies in the slab in neither scene).
 */
int CameraInsideScene(vtkHAVSMapperBase* mapper, const std::string& mesh, int size,
  const std::function<void()>& afterFrame = nullptr);
}

#endif
