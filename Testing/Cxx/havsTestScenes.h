/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestScenes.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestScenes.h
 * @brief Scenes of the vtkHAVS tests: properties, windows, one volume in a renderer, cameras.
 */
#ifndef havsTestScenes_h
#define havsTestScenes_h

#include "havsTestProperties.h" // the scenes take these properties
#include "vtkSmartPointer.h"

#include <string>

class vtkAbstractVolumeMapper;
class vtkDataObject;
class vtkHAVSVolumeMapper;
class vtkRenderWindow;
class vtkRenderer;
class vtkUnstructuredGrid;
class vtkVolume;
class vtkVolumeProperty;

namespace havstest
{
/// Render window from the project's factory, of the given size, no multisampling.
vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height);

/// A window of the factory with one renderer showing `grid` through `mapper`.
struct VolumeScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkVolume> Volume;
};
VolumeScene MakeScene(vtkDataObject* grid, vtkAbstractVolumeMapper* mapper,
  vtkVolumeProperty* property, int width, int height);

/**
 * The centroid face order at k = 6 (the mapper's defaults before issue 16
 * made MPVO at k = 2 the default): for the tests of the k-buffer itself
 * (ordering, paths, the software k-buffer, k = 1 controls), which need the
 * order to be nearly, not exactly, sorted. Later SetKBufferSize calls win.
 */
void UseCentroidOrder(vtkHAVSVolumeMapper* mapper);

/// An opaque sphere (centre 0.55, 0.5, 0.45, radius 0.3) added to the
/// renderer: inside the unit box of the opaque-geometry tests.
void AddOpaqueSphere(vtkRenderer* renderer);

/// Places the camera: looking at the grid's centre from (azimuth, elevation)
/// degrees, perspective unless parallel is set; resets the clipping range.
void PlaceCamera(vtkRenderer* renderer, double azimuth, double elevation, bool parallel);

/// The mesh of the camera-inside scenes: "box" (a 10^3 box of unit size) or a
/// data set of vtkHAVSDataSets::Load; nullptr when it does not load.
vtkSmartPointer<vtkUnstructuredGrid> LoadInsideMesh(const std::string& mesh);

/**
 * The camera inside `grid` (the cell projection's and the ray caster's
 * inside scenes): perspective, 60 degrees, the near plane at 5 % of the
 * grid's length so that the slab it cuts off shows. In the box off its face
 * planes (an eye on one sees whole lines of pixel rays graze faces, where
 * rasterizer and rays disagree whatever the mapper); in a data set inside
 * the flow, in front of the fin, looking downstream and a little up.
 */
void PlaceCameraInside(vtkRenderer* renderer, vtkUnstructuredGrid* grid, bool box);
}

#endif
