/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVolumeMapper.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSVolumeMapper.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSKBufferRenderer.h"
#include "vtkHAVSPlaneSection.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSVisibilityOrder.h"
#include "vtkIntArray.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPoints.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHAVSVolumeMapper);

namespace
{
/// Row-major VTK matrix -> column-major floats for OpenGL.
void ToGL(const vtkMatrix4x4* m, float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[c * 4 + r] = static_cast<float>(m->GetElement(r, c));
    }
  }
}

void Translation(vtkMatrix4x4* m, double x, double y, double z)
{
  m->Identity();
  m->SetElement(0, 3, x);
  m->SetElement(1, 3, y);
  m->SetElement(2, 3, z);
}

bool IsConstantOne(vtkPiecewiseFunction* f)
{
  if (!f)
  {
    return true;
  }
  double node[4];
  for (int i = 0; i < f->GetSize(); ++i)
  {
    f->GetNodeValue(i, node);
    if (node[1] != 1.0)
    {
      return false;
    }
  }
  return true;
}
}

struct vtkHAVSVolumeMapper::Internals
{
  vtkNew<vtkHAVSFaceSet> Faces;
  vtkNew<vtkHAVSFaceSorter> Sorter;
  vtkNew<vtkHAVSPreIntegrationTable> Table;
  vtkNew<vtkHAVSKBufferRenderer> Renderer;

  // Mesh as uploaded: points shifted by Shift (float precision for huge
  // coordinates), scalars mapped to [0, 1] over ScalarRange.
  std::vector<float> PointsMC;
  std::vector<float> Scalars;
  double Shift[3] = { 0, 0, 0 };
  double ScalarRange[2] = { 0, 1 };
  int Component = 0;
  bool MeshValid = false;
  vtkTimeStamp MeshBuildTime;
  vtkMTimeType MeshUploadTime = 0;

  std::vector<uint32_t> SortedTriangles;
  std::vector<uint8_t> SortedBoundary;
  bool OrderUploaded = false;

  vtkMTimeType TableUploadTime = 0;
  vtkTimeStamp TableBuildTime;

  bool WarnedShading = false;
  bool WarnedGradient = false;
  bool WarnedComponents = false;
  bool WarnedPath = false;
  bool WarnedK = false;
  bool WarnedPlanes = false;

  // What the mesh was built from: the grid, and the scalar selection.
  vtkUnstructuredGrid* MeshGrid = nullptr;
  std::string MeshScalarKey;
  double BoundsMC[6] = { 0, 0, 0, 0, 0, 0 };

  // The near and clipping planes of the frame (eye-relative world) and the
  // mesh's sections with them, as last uploaded.
  int PlaneCount = 0;
  float PlanesRC[7][4];
  std::vector<vtkHAVSKBufferRenderer::Section> Sections;
  // A plane that cuts the mesh: its index among the uploaded planes, whether
  // the rays enter the kept side there, its equation in model coordinates.
  struct SectionCut
  {
    int Index;
    bool Entering;
    std::array<double, 4> PlaneMC;
    bool operator==(const SectionCut& o) const
    {
      return this->Index == o.Index && this->Entering == o.Entering && this->PlaneMC == o.PlaneMC;
    }
  };
  std::vector<SectionCut> SectionCuts; // what the sections were made for
  vtkMTimeType SectionMeshTime = 0;
  bool SectionsUploaded = false;
  vtkNew<vtkHAVSPlaneSection> Sectioner;

  // MPVO: its adjacency (per mesh) and the view its order was made for.
  vtkNew<vtkHAVSVisibilityOrder> MPVO;
  vtkMTimeType MPVOMeshTime = 0;
  std::vector<double> MPVOKey;
  int LastOrderKind = -1;

  // The frame being rendered (set up by Render, used by DrawFrame).
  vtkHAVSKBufferRenderer::FrameParameters Frame;
  double Eye[3] = { 0, 0, 0 };
  double Direction[3] = { 0, 0, 1 };
  double GridToClip[16];
  int Viewport[2] = { 0, 0 };

  // Automatic order: what the choice was made for, and whether it is MPVO.
  std::vector<double> AutomaticKey;
  bool AutomaticMPVO = false;
};

//------------------------------------------------------------------------------
vtkHAVSVolumeMapper::vtkHAVSVolumeMapper()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkHAVSVolumeMapper::~vtkHAVSVolumeMapper()
{
  this->ReleaseGraphicsResources(nullptr);
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::IsKBufferPathSupported(vtkRenderWindow* window, int path)
{
  return vtkHAVSKBufferRenderer::IsPathSupported(
    vtkOpenGLRenderWindow::SafeDownCast(window), path);
}

//------------------------------------------------------------------------------
const char* vtkHAVSVolumeMapper::GetActiveKBufferPathName()
{
  return vtkHAVSKBufferRenderer::GetPathName(this->ActiveKBufferPath);
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSVolumeMapper::GetNumberOfFaces()
{
  return this->Internal->Faces->GetNumberOfFaces();
}

vtkIdType vtkHAVSVolumeMapper::GetNumberOfBoundaryFaces()
{
  return this->Internal->Faces->GetNumberOfBoundaryFaces();
}

vtkIdType vtkHAVSVolumeMapper::GetNumberOfTetrahedra()
{
  return this->Internal->Faces->GetNumberOfTetrahedra();
}

void vtkHAVSVolumeMapper::InvalidateFaceOrder()
{
  this->Internal->Sorter->Invalidate();
  this->Internal->MPVOKey.clear();
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::IsInputConvex()
{
  return this->Internal->MeshValid && this->Internal->Faces->IsConvex();
}

//------------------------------------------------------------------------------
vtkHAVSFaceSorter* vtkHAVSVolumeMapper::GetFaceSorter()
{
  return this->Internal->Sorter;
}

//------------------------------------------------------------------------------
vtkHAVSPreIntegrationTable* vtkHAVSVolumeMapper::GetPreIntegrationTable()
{
  return this->Internal->Table;
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::UpdateMesh(vtkVolume* volume)
{
  Internals& in = *this->Internal;
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(this->GetInput());
  if (!this->GetInput())
  {
    vtkErrorMacro("No input.");
    in.MeshValid = false;
    return false;
  }
  if (!grid)
  {
    vtkErrorMacro("The input is a " << this->GetInput()->GetClassName()
                                    << "; vtkHAVSVolumeMapper needs a vtkUnstructuredGrid.");
    in.MeshValid = false;
    return false;
  }
  // Rebuilt for a new or modified grid or another scalar selection only (not
  // for k, the table, the boundary mode or the clipping planes).
  std::ostringstream scalarKey;
  scalarKey << this->ScalarMode << " " << this->ArrayAccessMode << " " << this->ArrayId << " "
            << (this->ArrayName ? this->ArrayName : "");
  const bool needed = grid != in.MeshGrid || grid->GetMTime() > in.MeshBuildTime ||
    scalarKey.str() != in.MeshScalarKey || !in.MeshBuildTime.GetMTime();
  if (!needed)
  {
    return in.MeshValid;
  }
  in.MeshGrid = grid;
  in.MeshScalarKey = scalarKey.str();
  in.MeshBuildTime.Modified();
  in.MeshValid = false;
  in.OrderUploaded = false;
  in.Sorter->Invalidate();

  if (grid->GetNumberOfPoints() == 0 || grid->GetNumberOfCells() == 0)
  {
    vtkErrorMacro("The input grid is empty (" << grid->GetNumberOfPoints() << " points, "
                                              << grid->GetNumberOfCells() << " cells).");
    return false;
  }

  int cellFlag = -1;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(grid, this->ScalarMode,
    this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars)
  {
    vtkErrorMacro("The input has no scalars to render (scalar mode "
      << this->GetScalarModeAsString() << (this->ArrayName ? ", array " : "")
      << (this->ArrayName ? this->ArrayName : "") << ").");
    return false;
  }
  if (cellFlag != 0)
  {
    vtkErrorMacro("Cell scalars are not supported by vtkHAVSVolumeMapper yet; use point scalars "
                  "(e.g. vtkCellDataToPointData).");
    return false;
  }

  this->UpdateProgress(0.0);
  if (!in.Faces->Build(grid))
  {
    vtkErrorMacro("No tetrahedra to render in the input.");
    return false;
  }
  this->UpdateProgress(0.6);
  if (in.Faces->GetNumberOfSkippedCells() > 0)
  {
    vtkWarningMacro(<< in.Faces->GetNumberOfSkippedCells()
                    << " cells that are not tetrahedra were skipped (tetrahedralize the input, "
                       "e.g. with vtkDataSetTriangleFilter).");
  }
  if (in.Faces->GetNumberOfDegenerateTetrahedra() > 0)
  {
    vtkWarningMacro(<< in.Faces->GetNumberOfDegenerateTetrahedra()
                    << " degenerate (zero-volume) tetrahedra were dropped.");
  }

  // Component: independent components are rendered from the first one.
  const int components = scalars->GetNumberOfComponents();
  in.Component = 0;
  vtkVolumeProperty* property = volume->GetProperty();
  if (components > 1 && !in.WarnedComponents)
  {
    vtkWarningMacro("The scalars have " << components << " components"
                                        << (property->GetIndependentComponents()
                                               ? " (independent)"
                                               : " (dependent)")
                                        << "; vtkHAVSVolumeMapper renders the first one only.");
    in.WarnedComponents = true;
  }

  // Points, shifted by the bounds centre so that floats keep their precision.
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  double bounds[6];
  grid->GetPoints()->GetBounds(bounds);
  for (int i = 0; i < 3; ++i)
  {
    in.Shift[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    in.BoundsMC[2 * i] = bounds[2 * i] - in.Shift[i];
    in.BoundsMC[2 * i + 1] = bounds[2 * i + 1] - in.Shift[i];
  }
  in.PointsMC.resize(3 * numPoints);
  vtkIdType nonFinitePoints = 0;
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double x[3];
    grid->GetPoint(p, x);
    for (int i = 0; i < 3; ++i)
    {
      double v = x[i] - in.Shift[i];
      if (!std::isfinite(v))
      {
        ++nonFinitePoints;
        v = 0.0;
      }
      in.PointsMC[3 * p + i] = static_cast<float>(v);
    }
  }
  if (nonFinitePoints > 0)
  {
    vtkErrorMacro(<< nonFinitePoints << " non-finite point coordinates; the mesh is not rendered.");
    return false;
  }

  // Scalars mapped to [0, 1] over the finite range; NaN/Inf replaced.
  double range[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
  vtkIdType nonFinite = 0;
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    const double s = scalars->GetComponent(p, in.Component);
    if (std::isfinite(s))
    {
      range[0] = std::min(range[0], s);
      range[1] = std::max(range[1], s);
    }
    else
    {
      ++nonFinite;
    }
  }
  if (range[0] > range[1])
  {
    vtkErrorMacro("Every scalar value is NaN or infinite; nothing to render.");
    return false;
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " NaN/infinite scalar values were replaced by the lowest finite value ("
                    << range[0] << ").");
  }
  in.ScalarRange[0] = range[0];
  in.ScalarRange[1] = range[1];
  const double span = range[1] - range[0];
  in.Scalars.resize(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double s = scalars->GetComponent(p, in.Component);
    if (!std::isfinite(s))
    {
      s = range[0];
    }
    in.Scalars[p] = span > 0.0 ? static_cast<float>((s - range[0]) / span) : 0.0f;
  }
  this->UpdateProgress(1.0);
  in.MeshValid = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::UpdateTable(vtkVolume* volume)
{
  Internals& in = *this->Internal;
  vtkVolumeProperty* property = volume->GetProperty();
  if (property->GetShade(in.Component) && !in.WarnedShading)
  {
    vtkWarningMacro("Shading is not supported by vtkHAVSVolumeMapper; the volume is unshaded.");
    in.WarnedShading = true;
  }
  if (!in.WarnedGradient && !property->GetDisableGradientOpacity(in.Component) &&
    property->HasGradientOpacity(in.Component) &&
    !IsConstantOne(property->GetGradientOpacity(in.Component)))
  {
    vtkWarningMacro("Gradient opacity is not supported by vtkHAVSVolumeMapper; it is ignored.");
    in.WarnedGradient = true;
  }

  // The longest segment inside one tetrahedron is its longest edge; in world
  // space after the volume's matrix, at most that times the largest stretch.
  vtkMatrix4x4* m = volume->GetMatrix();
  double stretch = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double column[3] = { m->GetElement(0, c), m->GetElement(1, c), m->GetElement(2, c) };
    stretch = std::max(stretch, vtkMath::Norm(column));
  }
  const double maxLength = std::max(in.Faces->GetLongestEdge() * stretch, 1e-30);

  in.Table->SetScalarResolution(this->TableScalarResolution);
  in.Table->SetLengthResolution(this->TableLengthResolution);
  if (in.Table->NeedsRebuild(property, in.Component, in.ScalarRange, maxLength))
  {
    this->UpdateProgress(0.0);
    const double start = vtkTimerLog::GetUniversalTime();
    if (!in.Table->Build(property, in.Component, in.ScalarRange, maxLength))
    {
      vtkErrorMacro("The pre-integrated transfer-function table could not be built.");
      return false;
    }
    this->LastTableSeconds = vtkTimerLog::GetUniversalTime() - start;
    in.TableBuildTime.Modified();
    this->UpdateProgress(1.0);
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkHAVSVolumeMapper::ChoosePath(vtkRenderWindow* window)
{
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (this->KBufferPath != KBufferPathAutomatic)
  {
    if (vtkHAVSKBufferRenderer::IsPathSupported(glWindow, this->KBufferPath))
    {
      return this->KBufferPath;
    }
    if (!this->Internal->WarnedPath)
    {
      vtkWarningMacro("The k-buffer path " << vtkHAVSKBufferRenderer::GetPathName(this->KBufferPath)
                                           << " is not supported by this OpenGL context; "
                                              "choosing automatically.");
      this->Internal->WarnedPath = true;
    }
  }
  for (int path : { KBufferPathFramebufferFetch, KBufferPathFragmentShaderInterlock,
         KBufferPathFragmentLists })
  {
    if (vtkHAVSKBufferRenderer::IsPathSupported(glWindow, path))
    {
      return path;
    }
  }
  return 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::UpdatePlanes(vtkRenderer* renderer, const double eye[3],
  const double direction[3], bool parallel, const vtkMatrix4x4* modelToEyeRelative)
{
  Internals& in = *this->Internal;
  // Planes in eye-relative world coordinates (x_RC = world - eye), kept where
  // dot(n, x_RC) + w >= 0, with whether the rays enter the kept side there.
  struct PlaneRC
  {
    double Equation[4];
    bool Entering;
  };
  std::vector<PlaneRC> planes;

  // The near plane, a hair beyond the camera's (GL clips there; the section
  // must lie just inside): only when it cuts the mesh's bounds.
  double range[2];
  renderer->GetActiveCamera()->GetClippingRange(range);
  const double nearDepth = range[0] + 1e-5 * (range[1] - range[0]);
  planes.push_back({ { direction[0], direction[1], direction[2], -nearDepth }, true });

  vtkPlaneCollection* clipping = this->ClippingPlanes;
  const int userPlanes = clipping ? clipping->GetNumberOfItems() : 0;
  if (userPlanes > 6 && !in.WarnedPlanes)
  {
    vtkWarningMacro(<< userPlanes << " clipping planes; vtkHAVSVolumeMapper uses the first 6.");
    in.WarnedPlanes = true;
  }
  for (int i = 0; i < std::min(userPlanes, 6); ++i)
  {
    vtkPlane* plane = clipping->GetItem(i);
    double n[3], origin[3];
    plane->GetNormal(n);
    plane->GetOrigin(origin);
    if (vtkMath::Norm(n) == 0.0)
    {
      continue;
    }
    // World: n.x - n.origin >= 0 is kept (as VTK's other mappers).
    const double w = vtkMath::Dot(n, eye) - vtkMath::Dot(n, origin);
    const bool entering = parallel ? vtkMath::Dot(n, direction) > 0.0 : w < 0.0;
    planes.push_back({ { n[0], n[1], n[2], w }, entering });
  }

  // Each plane in model coordinates: the sections are cut there.
  in.PlaneCount = 0;
  std::vector<Internals::SectionCut> sectionCuts;
  for (size_t i = 0; i < planes.size(); ++i)
  {
    double planeMC[4];
    for (int c = 0; c < 4; ++c)
    {
      planeMC[c] = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        planeMC[c] += planes[i].Equation[r] * modelToEyeRelative->GetElement(r, c);
      }
    }
    planeMC[3] += planes[i].Equation[3];
    const bool cuts = vtkHAVSPlaneSection::CutsBox(planeMC, in.BoundsMC);
    const double corner[3] = { in.BoundsMC[0], in.BoundsMC[2], in.BoundsMC[4] };
    const bool allDiscarded = !cuts &&
      planeMC[0] * corner[0] + planeMC[1] * corner[1] + planeMC[2] * corner[2] + planeMC[3] < 0.0;
    if (!cuts && !allDiscarded)
    {
      continue; // the whole mesh is kept: the plane changes nothing
    }
    const int index = in.PlaneCount++;
    for (int c = 0; c < 4; ++c)
    {
      in.PlanesRC[index][c] = static_cast<float>(planes[i].Equation[c]);
    }
    if (cuts && this->PlaneSections)
    {
      sectionCuts.push_back(
        { index, planes[i].Entering, { planeMC[0], planeMC[1], planeMC[2], planeMC[3] } });
    }
  }

  // Sections, only when a plane or the mesh changed.
  if (sectionCuts == in.SectionCuts && in.SectionMeshTime == in.MeshBuildTime.GetMTime())
  {
    return false;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  in.SectionCuts = sectionCuts;
  in.SectionMeshTime = in.MeshBuildTime.GetMTime();
  in.Sections.clear();
  this->LastSectionTriangles = 0;
  for (const Internals::SectionCut& cut : sectionCuts)
  {
    vtkHAVSKBufferRenderer::Section section;
    section.PlaneIndex = cut.Index;
    section.Entering = cut.Entering;
    this->LastSectionTriangles += in.Sectioner->Compute(in.Faces->GetTetrahedra(), in.PointsMC,
      in.Scalars, cut.PlaneMC.data(), section.PointsMC, section.Scalars);
    in.Sections.push_back(std::move(section));
  }
  this->LastSectionSeconds = vtkTimerLog::GetUniversalTime() - start;
  in.SectionsUploaded = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& in = *this->Internal;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkHAVSVolumeMapper needs an OpenGL render window.");
    return;
  }
  if (this->GetNumberOfInputConnections(0) > 0)
  {
    this->GetInputAlgorithm()->Update();
  }
  if (!this->UpdateMesh(volume) || !this->UpdateTable(volume))
  {
    return;
  }

  int width = 0, height = 0, originX = 0, originY = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &originX, &originY);
  if (width <= 0 || height <= 0)
  {
    return;
  }

  const int path = this->ChoosePath(window);
  if (path == 0)
  {
    vtkErrorMacro("This OpenGL context has none of the k-buffer paths (it needs OpenGL 4.3 with "
                  "EXT_shader_framebuffer_fetch, or fragment-shader interlock, or OpenGL 4.4).");
    return;
  }
  int k = this->KBufferSize;
  const int maxK = vtkHAVSKBufferRenderer::GetMaximumK(path);
  if (k > maxK)
  {
    if (!in.WarnedK)
    {
      vtkWarningMacro("k = " << k << " exceeds the " << vtkHAVSKBufferRenderer::GetPathName(path)
                             << " path's maximum; using k = " << maxK << ".");
      in.WarnedK = true;
    }
    k = maxK;
  }

  // Matrices, in double; the eye-relative ones keep precision far from the origin.
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* volumeMatrix = volume->GetMatrix();
  vtkNew<vtkMatrix4x4> shift, modelToWorld, worldToClip, eyeShift, mcrc, mcdc, clipToWorld, dcrc;
  Translation(shift, in.Shift[0], in.Shift[1], in.Shift[2]);
  vtkMatrix4x4::Multiply4x4(volumeMatrix, shift, modelToWorld);
  worldToClip->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  double eye[3], direction[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  Translation(eyeShift, -eye[0], -eye[1], -eye[2]);
  vtkMatrix4x4::Multiply4x4(eyeShift, modelToWorld, mcrc);
  vtkMatrix4x4::Multiply4x4(worldToClip, modelToWorld, mcdc);
  vtkMatrix4x4::Invert(worldToClip, clipToWorld);
  vtkMatrix4x4::Multiply4x4(eyeShift, clipToWorld, dcrc);

  vtkHAVSKBufferRenderer::FrameParameters frame;
  ToGL(mcrc, frame.MCRC);
  ToGL(mcdc, frame.MCDC);
  ToGL(dcrc, frame.DCRC);
  for (int i = 0; i < 3; ++i)
  {
    frame.DirectionOfProjection[i] = static_cast<float>(direction[i]);
  }
  frame.Parallel = camera->GetParallelProjection() != 0;
  frame.FlipFacing = volumeMatrix->Determinant() < 0.0;
  frame.Path = path;
  frame.K = k;
  switch (this->BlendMode)
  {
    case vtkUnstructuredGridVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      frame.BlendMode = 1;
      break;
    case vtkHAVSVolumeMapper::MINIMUM_INTENSITY_BLEND:
      frame.BlendMode = 2;
      break;
    case vtkUnstructuredGridVolumeMapper::COMPOSITE_BLEND:
      frame.BlendMode = 0;
      break;
    default:
      vtkErrorMacro("Blend mode " << this->BlendMode
                                  << " is not supported by vtkHAVSVolumeMapper (composite, "
                                     "maximum and minimum intensity are).");
      return;
  }
  frame.TerminationOpacity = static_cast<float>(this->EarlyRayTerminationOpacity);
  frame.MeasureStages = this->MeasureStageTimes;
  frame.KeepResult = this->KeepFloatResult;
  frame.RasterBoundOnly = this->FaceRasterBoundMode;
  frame.Tagging = this->BoundaryMode == BoundaryTagging ||
    (this->BoundaryMode == BoundaryAutomatic && !in.Faces->IsConvex());
  frame.GapLength = this->BoundaryMode == BoundaryGapLength
    ? static_cast<float>(in.Table->GetMaxLength())
    : 3.0e38f;
  this->LastTagging = frame.Tagging;

  // Near and clipping planes: the discard test, and the sections.
  this->UpdatePlanes(renderer, eye, direction, frame.Parallel, mcrc);
  frame.PlaneCount = in.PlaneCount;
  std::copy(&in.PlanesRC[0][0], &in.PlanesRC[0][0] + 4 * in.PlaneCount, &frame.PlanesRC[0][0]);
  this->LastPlaneCount = in.PlaneCount;

  // The view the face order is made for.
  std::copy(eye, eye + 3, in.Eye);
  std::copy(direction, direction + 3, in.Direction);
  {
    vtkNew<vtkMatrix4x4> gridToClip;
    vtkMatrix4x4::Multiply4x4(worldToClip, volumeMatrix, gridToClip);
    vtkMatrix4x4::DeepCopy(in.GridToClip, gridToClip);
  }
  in.Viewport[0] = width;
  in.Viewport[1] = height;

  // Automatic: the centroid order while the k-buffer keeps up with it; the
  // first frame it does not (order violations) is drawn again with MPVO,
  // which then stays for this mesh, k and path.
  int order = this->VisibilityOrder;
  bool probe = false;
  if (this->VisibilityOrder == VisibilityOrderAutomatic)
  {
    const std::vector<double> key = { static_cast<double>(in.MeshBuildTime.GetMTime()),
      static_cast<double>(k), static_cast<double>(path) };
    if (key != in.AutomaticKey)
    {
      in.AutomaticKey = key;
      in.AutomaticMPVO = false;
    }
    order = in.AutomaticMPVO ? VisibilityOrderMPVO : VisibilityOrderCentroid;
    probe = !in.AutomaticMPVO && frame.BlendMode == 0 && !frame.RasterBoundOnly;
  }
  frame.CountOrderViolations = this->CountOrderViolations || probe;
  frame.Composite = !probe;
  in.Frame = frame;
  if (!this->DrawFrame(renderer, window, volume, order))
  {
    return;
  }
  if (probe)
  {
    if (this->LastOrderViolations > 0)
    {
      in.AutomaticMPVO = true;
      in.Frame.Composite = true;
      if (!this->DrawFrame(renderer, window, volume, VisibilityOrderMPVO))
      {
        return;
      }
    }
    else if (!in.Renderer->CompositeLastResult(renderer))
    {
      return;
    }
  }
  this->ActiveKBufferPath = path;
  this->ActiveKBufferSize = frame.BlendMode == 0 ? k : 0;
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::DrawFrame(
  vtkRenderer* renderer, vtkOpenGLRenderWindow* window, vtkVolume* volume, int orderKind)
{
  Internals& in = *this->Internal;
  vtkHAVSKBufferRenderer::FrameParameters& frame = in.Frame;
  const double* eye = in.Eye;
  const double* direction = in.Direction;
  vtkMatrix4x4* volumeMatrix = volume->GetMatrix();

  // Face order: composite needs one; the extremum modes do not.
  const double sortStart = vtkTimerLog::GetUniversalTime();
  bool orderChanged = false;
  const std::vector<uint32_t>* order = nullptr;
  this->LastCycleBreaks = 0;
  if (frame.BlendMode == 0 && orderKind == VisibilityOrderMPVO)
  {
    if (in.MPVOMeshTime != in.MeshBuildTime.GetMTime())
    {
      in.MPVO->Build(in.Faces, vtkUnstructuredGrid::SafeDownCast(this->GetInput()));
      in.MPVOMeshTime = in.MeshBuildTime.GetMTime();
      in.MPVOKey.clear();
    }
    // The eye and the direction of projection in the grid's coordinates.
    vtkNew<vtkMatrix4x4> worldToModel;
    vtkMatrix4x4::Invert(volumeMatrix, worldToModel);
    double eyeModel[4] = { eye[0], eye[1], eye[2], 1.0 }, directionModel[4] = { direction[0],
      direction[1], direction[2], 0.0 };
    worldToModel->MultiplyPoint(eyeModel, eyeModel);
    worldToModel->MultiplyPoint(directionModel, directionModel);
    for (int i = 0; i < 3; ++i)
    {
      eyeModel[i] /= eyeModel[3];
    }
    std::vector<double> key = { eyeModel[0], eyeModel[1], eyeModel[2], directionModel[0],
      directionModel[1], directionModel[2], frame.Parallel ? 1.0 : 0.0,
      static_cast<double>(this->NonConvexMethod) };
    if (this->NonConvexMethod == NonConvexBoundaryLayers && !in.MPVO->IsMeshConvex())
    {
      // The boundary layers are sampled at this frame's pixels.
      key.insert(key.end(), in.GridToClip, in.GridToClip + 16);
      key.push_back(in.Viewport[0]);
      key.push_back(in.Viewport[1]);
    }
    if (key != in.MPVOKey || in.LastOrderKind != VisibilityOrderMPVO)
    {
      in.MPVO->SetNonConvexMethod(this->NonConvexMethod);
      in.MPVO->SetViewSampling(in.GridToClip, in.Viewport[0], in.Viewport[1]);
      in.MPVO->Sort(eyeModel, directionModel, frame.Parallel);
      in.MPVOKey = key;
      orderChanged = true;
    }
    this->LastCycleBreaks = in.MPVO->GetNumberOfCycleBreaks();
    order = &in.MPVO->GetOrder();
    if (static_cast<vtkIdType>(order->size()) != in.Faces->GetNumberOfFaces())
    {
      vtkErrorMacro("The MPVO order could not be made for this mesh; using the centroid order.");
      order = nullptr;
      in.LastOrderKind = -1;
    }
  }
  if (frame.BlendMode == 0 && !order)
  {
    double m[16];
    vtkMatrix4x4::DeepCopy(m, volumeMatrix);
    if (in.LastOrderKind != VisibilityOrderCentroid)
    {
      in.Sorter->Invalidate();
    }
    orderChanged = in.Sorter->Sort(in.Faces, m, eye, direction, frame.Parallel);
    order = &in.Sorter->GetOrder();
  }
  in.LastOrderKind = frame.BlendMode == 0 && order == &in.MPVO->GetOrder()
    ? VisibilityOrderMPVO
    : (frame.BlendMode == 0 ? VisibilityOrderCentroid : -1);
  this->LastVisibilityOrder = in.LastOrderKind;
  if (orderChanged || in.SortedTriangles.empty())
  {
    const std::vector<uint32_t>& faceVertices = in.Faces->GetFaceVertices();
    const std::vector<uint8_t>& boundary = in.Faces->GetBoundaryFlags();
    const vtkIdType numFaces = in.Faces->GetNumberOfFaces();
    in.SortedTriangles.resize(3 * numFaces);
    in.SortedBoundary.resize(numFaces);
    for (vtkIdType i = 0; i < numFaces; ++i)
    {
      const uint32_t f = order ? (*order)[i] : static_cast<uint32_t>(i);
      in.SortedTriangles[3 * i] = faceVertices[3 * f];
      in.SortedTriangles[3 * i + 1] = faceVertices[3 * f + 1];
      in.SortedTriangles[3 * i + 2] = faceVertices[3 * f + 2];
      in.SortedBoundary[i] = boundary[f];
    }
    in.OrderUploaded = false;
  }
  this->LastSortReused = !orderChanged;
  this->LastSortSeconds = vtkTimerLog::GetUniversalTime() - sortStart;

  // Uploads: everything after a new context, else what changed.
  const bool fresh = in.Renderer->PrepareWindow(window);
  if (fresh || in.MeshUploadTime < in.MeshBuildTime.GetMTime())
  {
    in.Renderer->SetGeometry(in.PointsMC, in.Scalars);
    in.MeshUploadTime = in.MeshBuildTime.GetMTime();
    in.OrderUploaded = false;
  }
  if (fresh || !in.OrderUploaded)
  {
    in.Renderer->SetFaceOrder(in.SortedTriangles, in.SortedBoundary);
    in.OrderUploaded = true;
  }
  if (fresh || !in.SectionsUploaded)
  {
    in.Renderer->SetSections(in.Sections);
    in.SectionsUploaded = true;
  }
  if (fresh || in.TableUploadTime < in.TableBuildTime.GetMTime())
  {
    in.Renderer->SetTable(in.Table->GetTable(), in.Table->GetScalarResolution(),
      in.Table->GetLengthResolution(), in.Table->GetMaxLength(), in.Table->GetTransferFunction1D());
    in.TableUploadTime = in.TableBuildTime.GetMTime();
  }

  if (!in.Renderer->Render(renderer, frame))
  {
    return false;
  }
  this->LastOrderViolations = static_cast<vtkIdType>(in.Renderer->GetLastOrderViolations());
  this->LastDrawSeconds = in.Renderer->GetLastDrawSeconds();
  this->LastFlushSeconds = in.Renderer->GetLastFlushSeconds();
  this->LastCompositeSeconds = in.Renderer->GetLastCompositeSeconds();
  return true;
}

//------------------------------------------------------------------------------
int vtkHAVSVolumeMapper::GetLastOrderViolationPixels(vtkIntArray* pixels)
{
  const std::vector<int>& xy = this->Internal->Renderer->GetLastViolationPixels();
  if (pixels)
  {
    pixels->SetNumberOfComponents(2);
    pixels->SetNumberOfTuples(static_cast<vtkIdType>(xy.size() / 2));
    std::copy(xy.begin(), xy.end(), pixels->GetPointer(0));
  }
  return static_cast<int>(xy.size() / 2);
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSVolumeMapper::GetNumberOfImaginaryCells()
{
  return this->Internal->MPVO->GetNumberOfImaginaryCells();
}

//------------------------------------------------------------------------------
double vtkHAVSVolumeMapper::GetConvexificationSeconds()
{
  return this->Internal->MPVO->GetConvexificationSeconds();
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSVolumeMapper::GetLastBoundaryRelations()
{
  return this->Internal->MPVO->GetNumberOfBoundaryRelations();
}

//------------------------------------------------------------------------------
double vtkHAVSVolumeMapper::GetLastBoundaryLayerSeconds()
{
  return this->Internal->MPVO->GetLastBoundaryLayerSeconds();
}

//------------------------------------------------------------------------------
bool vtkHAVSVolumeMapper::GetFloatResult(vtkFloatArray* rgba, int size[2])
{
  const std::vector<float>& result = this->Internal->Renderer->GetLastResult();
  if (!rgba || result.empty())
  {
    return false;
  }
  size[0] = this->Internal->Renderer->GetLastResultWidth();
  size[1] = this->Internal->Renderer->GetLastResultHeight();
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(size[0]) * size[1]);
  std::copy(result.begin(), result.end(), rgba->GetPointer(0));
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Renderer->ReleaseGraphicsResources(window);
  this->Internal->OrderUploaded = false;
  this->Internal->SectionsUploaded = false;
}

//------------------------------------------------------------------------------
void vtkHAVSVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "KBufferSize: " << this->KBufferSize << "\n";
  os << indent << "KBufferPath (requested): "
     << (this->KBufferPath == KBufferPathAutomatic
            ? "Automatic"
            : vtkHAVSKBufferRenderer::GetPathName(this->KBufferPath))
     << "\n";
  os << indent << "Active k-buffer path: " << this->GetActiveKBufferPathName()
     << " (k = " << this->ActiveKBufferSize << ")\n";
  os << indent << "EarlyRayTerminationOpacity: " << this->EarlyRayTerminationOpacity << "\n";
  os << indent << "Table: " << this->TableScalarResolution << " x " << this->TableScalarResolution
     << " x " << this->TableLengthResolution << "\n";
  os << indent << "MeasureStageTimes: " << this->MeasureStageTimes << "\n";
  os << indent << "KeepFloatResult: " << this->KeepFloatResult << "\n";
  os << indent << "FaceRasterBoundMode: " << this->FaceRasterBoundMode << "\n";
  const char* orders[] = { "Centroid", "MPVO", "Automatic" };
  const char* methods[] = { "Ignore", "BoundaryLayers", "Convexification" };
  os << indent << "VisibilityOrder: " << orders[this->VisibilityOrder] << " (last frame: "
     << (this->LastVisibilityOrder >= 0 ? orders[this->LastVisibilityOrder] : "none")
     << ", cycle breaks " << this->LastCycleBreaks << ")\n";
  os << indent << "NonConvexMethod: " << methods[this->NonConvexMethod] << "\n";
  os << indent << "CountOrderViolations: " << this->CountOrderViolations
     << " (last frame: " << this->LastOrderViolations << ")\n";
  static const char* const boundaryModes[] = { "Automatic", "Tagging", "Ignore", "GapLength" };
  os << indent << "BoundaryMode: " << boundaryModes[this->BoundaryMode]
     << " (last frame tagged: " << this->LastTagging << ")\n";
  os << indent << "Last frame planes: " << this->LastPlaneCount << ", section triangles "
     << this->LastSectionTriangles << " (" << this->LastSectionSeconds << " s)\n";
  os << indent << "Last stage times (s): sort " << this->LastSortSeconds << ", draw "
     << this->LastDrawSeconds << ", flush " << this->LastFlushSeconds << ", composite "
     << this->LastCompositeSeconds << ", table " << this->LastTableSeconds << "\n";
  os << indent << "Faces: " << this->Internal->Faces->GetNumberOfFaces() << " ("
     << this->Internal->Faces->GetNumberOfBoundaryFaces() << " boundary), tetrahedra "
     << this->Internal->Faces->GetNumberOfTetrahedra() << "\n";
}
