/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTestUtilities.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSTestUtilities.h
 * @brief Small helpers shared by the vtkHAVS ctest programs (not part of the module).
 */
#ifndef vtkHAVSTestUtilities_h
#define vtkHAVSTestUtilities_h

#include <cmath>
#include <iostream>
#include <string>

namespace havstest
{
/// Directory of the real data sets (shared/data), from HAVS_DATA_DIR.
std::string DataDir();
/// Directory where tests write images and logs, from HAVS_TEST_OUTPUT_DIR.
std::string OutputDir();
/// Directory of the baseline images, from HAVS_BASELINE_DIR.
std::string BaselineDir();

/// Counts failed checks; a test returns Failures() ? EXIT_FAILURE : EXIT_SUCCESS.
int& Failures();

/// Prints and counts a failed check.
bool Check(bool condition, const std::string& what);
/// |a - b| <= tol, printed on failure.
bool CheckNear(double a, double b, double tol, const std::string& what);
}

#endif

#include "vtkSmartPointer.h"

#include <functional>
#include <vector>

class vtkColorTransferFunction;
class vtkPiecewiseFunction;
class vtkRenderWindow;
class vtkRenderer;
class vtkUnstructuredGrid;
class vtkVolume;
class vtkVolumeMapper;
class vtkVolumeProperty;
class vtkImageData;
class vtkUnsignedCharArray;

namespace havstest
{
/// A box [0,nx*h]x[0,ny*h]x[0,nz*h] of 5 tets per cube (vtkDataSetTriangleFilter),
/// point scalar "s" = a + b*z.
vtkSmartPointer<vtkUnstructuredGrid> MakeBox(int nx, int ny, int nz, double h, double a, double b);

/// The cells of `grid` whose centroid satisfies `keep`.
vtkSmartPointer<vtkUnstructuredGrid> KeepCells(
  vtkUnstructuredGrid* grid, const std::function<bool(const double*)>& keep);
/// Non-convex meshes: a vtkRTAnalyticSource thresholded at 160 (scalars
/// RTData), a hollow sphere (a cavity), a torus, and two 1 x 1 x 1 blocks of
/// 6^3 cubes (longest edge 0.29) with a gap of 0.08 between them along x.
vtkSmartPointer<vtkUnstructuredGrid> ThresholdedWavelet();
vtkSmartPointer<vtkUnstructuredGrid> HollowSphere();
vtkSmartPointer<vtkUnstructuredGrid> Torus();
vtkSmartPointer<vtkUnstructuredGrid> TwoBlocks();
/// One of the above by name (wavelet, hollowsphere, torus, twoblocks), else
/// ReadDataSet(name).
vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const std::string& name);

/// PLOT3D data set from shared/data, tetrahedralized; function 100 density, 110 pressure...
vtkSmartPointer<vtkUnstructuredGrid> ReadPlot3D(
  const std::string& xyz, const std::string& q, int scalarFunction);

/// A data set of shared/data by name, tetrahedralized as its README says:
/// bluntfin (density), loxpost (PLOT3D, pressure), combustor (density),
/// loxpostvtk (post.vtk, Pressure). nullptr when it cannot be read.
vtkSmartPointer<vtkUnstructuredGrid> ReadDataSet(const std::string& name);

/// shared/data/post.vtk with its Pressure array as the active scalars.
vtkSmartPointer<vtkUnstructuredGrid> ReadLoxPostVtk();

/// A property with the given constant colour and opacity.
vtkSmartPointer<vtkVolumeProperty> MakeConstantProperty(
  double r, double g, double b, double opacity, double unitDistance);

/// A property ramping opacity and colour over [lo, hi] (not empty, not opaque).
vtkSmartPointer<vtkVolumeProperty> MakeRampProperty(double lo, double hi, double maxOpacity,
  double unitDistance);

/// MakeRampProperty over the grid's scalar range, opacity 0.8 at the top,
/// unit distance an eighth of the bounds' diagonal.
vtkSmartPointer<vtkVolumeProperty> MakeRampPropertyFor(vtkUnstructuredGrid* grid);

/// Render window from the project's factory, of the given size.
vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height);

/// Reads the window's RGBA (float, [0,1]) after a render.
std::vector<float> ReadRGBA(vtkRenderWindow* window);

/// RMSE and maximum absolute difference over RGBA in [0,1].
struct ImageDifference
{
  double RMSE = 0;
  double Max = 0;
  double FractionOver1 = 0; ///< share of pixels with a channel off by more than 1/255
};
/// RMSE over all channels, largest channel error, share of pixels off by
/// more than 1/255; the ignoreWorst pixels with the largest error left out.
ImageDifference Compare(
  const std::vector<float>& a, const std::vector<float>& b, size_t ignoreWorst = 0);

/// Writes RGBA floats as PNG into the output directory.
void WritePNG(const std::vector<float>& rgba, int width, int height, const std::string& name);
/// Writes a 3-component unsigned char image as PNG into the output directory.
void WriteRGB(vtkUnsignedCharArray* rgb, int width, int height, const std::string& name);
/// Reads a PNG as RGBA floats; empty on failure.
std::vector<float> ReadPNG(const std::string& path, int* width, int* height);
}

class vtkHAVSVolumeMapper;
class vtkAbstractVolumeMapper;
class vtkObject;

namespace havstest
{
/// A window of the factory with one renderer showing `grid` through `mapper`.
struct VolumeScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkVolume> Volume;
};
VolumeScene MakeScene(vtkUnstructuredGrid* grid, vtkAbstractVolumeMapper* mapper,
  vtkVolumeProperty* property, int width, int height);

/// Places the camera: looking at the grid's centre from (azimuth, elevation)
/// degrees, perspective unless parallel is set; resets the clipping range.
void PlaceCamera(vtkRenderer* renderer, double azimuth, double elevation, bool parallel);

/// The mapper's kept float result (KeepFloatResultOn before rendering).
std::vector<float> FloatResult(vtkHAVSVolumeMapper* mapper);

/// Counts the error and warning events an object sends (and what they said).
struct Messages
{
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
};
/// Starts counting on `object`; the returned pointer stays valid while the
/// object lives.
Messages* CountMessages(vtkObject* object);

/// True when every value is finite.
bool AllFinite(const std::vector<float>& values);
}
