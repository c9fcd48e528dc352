/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSReferenceRenderer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSReferenceRenderer.h"

#include "vtkHAVSFaceRasterizer.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSIsoSurfaces.h"
#include "vtkHAVSPlaneSection.h"
#include "vtkHAVSPointGradients.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSReferenceRenderer);

//------------------------------------------------------------------------------
vtkHAVSReferenceRenderer::vtkHAVSReferenceRenderer()
{
  this->Image->SetNumberOfComponents(4);
}

vtkHAVSReferenceRenderer::~vtkHAVSReferenceRenderer() = default;

void vtkHAVSReferenceRenderer::SetInputData(vtkDataSet* grid)
{
  this->Source = grid;
  this->Input = nullptr; // split at the next ComputeFragments
  this->Modified();
}

void vtkHAVSReferenceRenderer::SetHigherOrderSubdivision(int level)
{
  level = std::max(0, std::min(level, 6));
  if (level != this->HigherOrderSubdivision)
  {
    this->HigherOrderSubdivision = level;
    this->Input = nullptr; // split again at the next ComputeFragments
    this->Modified();
  }
}

void vtkHAVSReferenceRenderer::SetProperty(vtkVolumeProperty* property)
{
  this->Property = property;
  this->Modified();
}

void vtkHAVSReferenceRenderer::SetCamera(vtkCamera* camera)
{
  this->Camera = camera;
  this->Modified();
}

void vtkHAVSReferenceRenderer::SetClippingPlanes(vtkPlaneCollection* planes)
{
  this->ClippingPlanes = planes;
  this->Modified();
}

vtkPlaneCollection* vtkHAVSReferenceRenderer::GetClippingPlanes()
{
  return this->ClippingPlanes;
}

void vtkHAVSReferenceRenderer::SetOpaqueDepth(vtkFloatArray* depth)
{
  this->OpaqueDepth = depth;
  this->Modified();
}

void vtkHAVSReferenceRenderer::AddTranslucentLayer(vtkFloatArray* depth, vtkFloatArray* rgba)
{
  if (!depth || !rgba || rgba->GetNumberOfComponents() != 4 ||
    depth->GetNumberOfTuples() != rgba->GetNumberOfTuples())
  {
    vtkErrorMacro("A translucent layer needs a depth image and an RGBA image of the same size.");
    return;
  }
  this->TranslucentLayers.push_back({ depth, rgba });
  this->Modified();
}

void vtkHAVSReferenceRenderer::AddTranslucentSurface(vtkPolyData* surface, const double rgba[4])
{
  if (!surface)
  {
    vtkErrorMacro("A translucent surface needs polygons.");
    return;
  }
  TranslucentSurface added;
  added.Surface = surface;
  std::copy_n(rgba, 4, added.RGBA);
  this->TranslucentSurfaces.push_back(added);
  this->Modified();
}

void vtkHAVSReferenceRenderer::RemoveAllTranslucentLayers()
{
  this->TranslucentLayers.clear();
  this->TranslucentSurfaces.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::SetVolumeMatrix(vtkMatrix4x4* matrix)
{
  if (matrix)
  {
    this->VolumeMatrix->DeepCopy(matrix);
  }
  else
  {
    this->VolumeMatrix->Identity();
  }
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIdType vtkHAVSReferenceRenderer::ComputeFoldedPixels(std::vector<uint8_t>& mask)
{
  const vtkIdType pixels = static_cast<vtkIdType>(this->Size[0]) * this->Size[1];
  mask.assign(static_cast<size_t>(std::max<vtkIdType>(pixels, 0)), 0);
  if ((this->Fragments.empty() || this->PixelStart.size() != static_cast<size_t>(pixels) + 1) &&
    !this->ComputeFragments())
  {
    return 0;
  }
  vtkNew<vtkHAVSVisibilityOrder> order;
  if (!order->Build(this->Faces, this->Input) || order->GetNumberOfFoldedFaces() == 0)
  {
    return 0;
  }
  const vtkIdType faces = this->Faces->GetNumberOfFaces();
  std::vector<uint8_t> foldedCell(static_cast<size_t>(this->Input->GetNumberOfCells()), 0);
  for (vtkIdType f = 0; f < faces; ++f)
  {
    if (order->IsFaceFolded(f))
    {
      vtkIdType c[2];
      order->GetFaceTetrahedra(f, c);
      foldedCell[c[0]] = 1;
      if (c[1] >= 0)
      {
        foldedCell[c[1]] = 1;
      }
    }
  }
  vtkIdType count = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    for (const Fragment* f = this->GetPixelFragmentsBegin(p);
         f != this->GetPixelFragmentsEnd(p) && !mask[p]; ++f)
    {
      if (f->Face < static_cast<uint32_t>(faces))
      {
        vtkIdType c[2];
        order->GetFaceTetrahedra(f->Face, c);
        mask[p] = foldedCell[c[0]] || (c[1] >= 0 && foldedCell[c[1]]) ? 1 : 0;
      }
    }
    count += mask[p];
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::SetLights(vtkLightCollection* lights)
{
  if (this->Lights != lights)
  {
    this->Lights = lights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::ReportProgress(double progress)
{
  double overall =
    this->ProgressRange[0] + progress * (this->ProgressRange[1] - this->ProgressRange[0]);
  this->InvokeEvent(vtkCommand::ProgressEvent, &overall);
}

//------------------------------------------------------------------------------
bool vtkHAVSReferenceRenderer::ComputeFragments()
{
  this->Fragments.clear();
  this->PixelStart.assign(1, 0);
  if (!this->Source || !this->Camera || this->Size[0] <= 0 || this->Size[1] <= 0)
  {
    vtkErrorMacro("Needs an input grid, a camera and a positive size.");
    return false;
  }
  if (!this->Input || this->Input->GetMTime() < this->Source->GetMTime())
  {
    this->Input =
      vtkHAVSTetrahedralizer::Tetrahedralize(this->Source, nullptr, this->HigherOrderSubdivision);
  }
  vtkDataArray* pointScalars = this->Input->GetPointData()->GetScalars();
  vtkDataArray* cellScalars = this->Input->GetCellData()->GetScalars();
  this->CellScalarsUsed = cellScalars && (this->UseCellScalars || !pointScalars);
  vtkDataArray* scalars = this->CellScalarsUsed ? cellScalars : pointScalars;
  if (!scalars)
  {
    vtkErrorMacro("The input has no point or cell scalars.");
    return false;
  }
  if (!this->FacesValid || this->FacesInput != this->Input ||
    this->Faces->GetBuildTime() < this->Input->GetMTime())
  {
    this->FacesInput = this->Input;
    this->FacesValid = this->Faces->Build(this->Input);
  }
  if (!this->FacesValid)
  {
    return false;
  }
  const bool cellData = this->CellScalarsUsed;
  this->ReportProgress(0.0);

  // World-space points and finite scalars (NaN/Inf -> the lowest finite value).
  const vtkIdType numPoints = this->Input->GetNumberOfPoints();
  std::vector<double> world(3 * numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double x[4] = { 0, 0, 0, 1 }, y[4];
    this->Input->GetPoint(p, x);
    this->VolumeMatrix->MultiplyPoint(x, y);
    for (int k = 0; k < 3; ++k)
    {
      world[3 * p + k] = y[k] / y[3];
    }
  }
  // The scalar range over the points (cells) the used cells have, as the mappers take it.
  const vtkIdType numValues = cellData ? this->Input->GetNumberOfCells() : numPoints;
  std::vector<double> values(static_cast<size_t>(numValues));
  std::vector<uint8_t> used;
  if (cellData)
  {
    used.assign(static_cast<size_t>(numValues), 0);
    for (uint32_t c : this->Faces->GetTetrahedronCells())
    {
      used[c] = 1;
    }
  }
  else
  {
    used = this->Faces->GetPointUse(numPoints);
  }
  double range[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
  for (vtkIdType p = 0; p < numValues; ++p)
  {
    values[p] = scalars->GetComponent(p, 0);
    if (std::isfinite(values[p]) && used[p])
    {
      range[0] = std::min(range[0], values[p]);
      range[1] = std::max(range[1], values[p]);
    }
  }
  if (range[0] > range[1])
  {
    range[0] = range[1] = 0.0;
  }
  for (double& v : values)
  {
    v = std::isfinite(v) ? v : range[0];
  }
  this->ScalarRange[0] = range[0];
  this->ScalarRange[1] = range[1];
  // Shaded isosurfaces: the points' gradients (world), interpolated at each fragment.
  this->ShadeIsoSurfaces = this->Property && this->Property->GetShade(0) && !cellData &&
    (this->BlendMode == vtkHAVSIsoSurfaces::IsoSurfaceBlend || this->IsoSurfacesInComposite);
  std::vector<double> pointGradients;
  if (this->ShadeIsoSurfaces)
  {
    vtkHAVSPointGradients::Compute(world, values, this->Faces->GetTetrahedra(), pointGradients);
  }
  auto interpolateGradient = [&](const uint32_t* ids, const double* weights, int count, float* out)
  {
    for (int k = 0; k < 3; ++k)
    {
      double g = 0.0;
      for (int i = 0; i < count; ++i)
      {
        g += weights[i] * pointGradients[3 * static_cast<size_t>(ids[i]) + k];
      }
      out[k] = static_cast<float>(g);
    }
  };

  // The camera, as the mapper sees it for an image of this size.
  vtkNew<vtkMatrix4x4> worldToClip;
  worldToClip->DeepCopy(this->Camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(this->Size[0]) / this->Size[1], -1, 1));
  double eye[3], directionOfProjection[3];
  this->Camera->GetPosition(eye);
  this->Camera->GetDirectionOfProjection(directionOfProjection);
  const bool parallel = this->Camera->GetParallelProjection() != 0;
  vtkNew<vtkHAVSFaceRasterizer> rasterizer;
  rasterizer->SetView(
    worldToClip->GetData(), eye, directionOfProjection, parallel, this->Size[0], this->Size[1]);
  this->PixelDirections.clear();
  if (this->ShadeIsoSurfaces)
  {
    this->PixelDirections.resize(3 * static_cast<size_t>(this->Size[0]) * this->Size[1]);
    for (int j = 0; j < this->Size[1]; ++j)
    {
      for (int i = 0; i < this->Size[0]; ++i)
      {
        const vtkHAVSFaceRasterizer::Ray ray = rasterizer->GetPixelRay(i, j);
        std::copy_n(ray.Direction, 3,
          &this->PixelDirections[3 * (static_cast<size_t>(j) * this->Size[0] + i)]);
      }
    }
  }
  const bool mirrored = this->VolumeMatrix->Determinant() < 0.0;

  // The near and clipping planes, world coordinates: kept where n.x + w >= 0.
  struct WorldPlane
  {
    double N[3];
    double W;
  };
  std::vector<WorldPlane> planes;
  if (this->NearPlaneClipping)
  {
    double range[2];
    this->Camera->GetClippingRange(range);
    const double* d = directionOfProjection;
    planes.push_back({ { d[0], d[1], d[2] }, -vtkMath::Dot(d, eye) - range[0] });
  }
  if (this->ClippingPlanes)
  {
    for (int i = 0; i < std::min(6, this->ClippingPlanes->GetNumberOfItems()); ++i)
    {
      vtkPlane* plane = this->ClippingPlanes->GetItem(i);
      WorldPlane p;
      plane->GetNormal(p.N);
      if (vtkMath::Norm(p.N) > 0.0)
      {
        p.W = -vtkMath::Dot(p.N, plane->GetOrigin());
        planes.push_back(p);
      }
    }
  }
  auto discarded = [&](const WorldPlane& plane, const double* x)
  { return vtkMath::Dot(plane.N, x) + plane.W < 0.0; };

  // Every face at every pixel centre (faces wholly on the discarded side of
  // a plane left out), each pixel's hits sorted by distance.
  const std::vector<uint32_t>& faceVertices = this->Faces->GetFaceVertices();
  const std::vector<uint32_t>& faceCells = this->Faces->GetFaceCells();
  const std::vector<uint8_t>& boundary = this->Faces->GetBoundaryFlags();
  const int width = this->Size[0], height = this->Size[1];
  rasterizer->Rasterize(world, faceVertices.data(), this->Faces->GetNumberOfFaces(),
    [&](vtkIdType f)
    {
      const uint32_t* ids = &faceVertices[3 * f];
      for (const WorldPlane& plane : planes)
      {
        if (discarded(plane, &world[3 * ids[0]]) && discarded(plane, &world[3 * ids[1]]) &&
          discarded(plane, &world[3 * ids[2]]))
        {
          return true;
        }
      }
      return false;
    });
  this->ReportProgress(0.5);
  const vtkIdType pixels = static_cast<vtkIdType>(width) * height;
  this->PixelStart = rasterizer->GetPixelStart();
  const std::vector<vtkHAVSFaceRasterizer::Hit>& hits = rasterizer->GetHits();
  this->Fragments.resize(hits.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(hits.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType h = begin; h < end; ++h)
      {
        const vtkHAVSFaceRasterizer::Hit& hit = hits[h];
        const uint32_t* ids = &faceVertices[3 * hit.Triangle];
        Fragment& f = this->Fragments[h];
        f.Distance = hit.Distance;
        f.Face = hit.Triangle;
        f.Boundary = boundary[hit.Triangle] != 0;
        f.Exit = f.Boundary && (mirrored ? hit.FrontFacing : !hit.FrontFacing);
        if (cellData)
        {
          // The cells on the near and far side (a boundary face's one cell on both).
          const bool eyeOnNormalSide = mirrored ? !hit.FrontFacing : hit.FrontFacing;
          uint32_t nearCell = faceCells[2 * hit.Triangle + (eyeOnNormalSide ? 0 : 1)];
          uint32_t farCell = faceCells[2 * hit.Triangle + (eyeOnNormalSide ? 1 : 0)];
          nearCell = nearCell != vtkHAVSFaceSet::NoCell ? nearCell : farCell;
          farCell = farCell != vtkHAVSFaceSet::NoCell ? farCell : nearCell;
          f.Scalar = values[nearCell];
          f.Behind = values[farCell];
        }
        else
        {
          f.Scalar = hit.Weights[0] * values[ids[0]] + hit.Weights[1] * values[ids[1]] +
            hit.Weights[2] * values[ids[2]];
          if (this->ShadeIsoSurfaces)
          {
            interpolateGradient(ids, hit.Weights, 3, f.Gradient);
          }
        }
      }
    });
  rasterizer->ReleaseHits();
  this->NumberOfStartedInside = 0;
  // The ray parameter where pixel p's ray meets window depth z.
  auto rayAtDepth = [&](vtkIdType p, const vtkHAVSFaceRasterizer::Ray& ray, float z)
  {
    const int i = static_cast<int>(p % width), j = static_cast<int>(p / width);
    double surface[3], d[3];
    rasterizer->Unproject(
      (i + 0.5) / width * 2.0 - 1.0, (j + 0.5) / height * 2.0 - 1.0, 2.0 * z - 1.0, surface);
    vtkMath::Subtract(surface, ray.Origin, d);
    return vtkMath::Dot(d, ray.Direction);
  };
  const float* opaque = this->OpaqueDepth &&
      this->OpaqueDepth->GetNumberOfValues() >= static_cast<vtkIdType>(width) * height
    ? this->OpaqueDepth->GetPointer(0)
    : nullptr;
  // The interval [t0, t1] of pixel p's ray that the first `count` planes keep
  // and the opaque surface leaves in front of it; false when a plane parallel
  // to the ray discards all of it.
  auto keptInterval =
    [&](vtkIdType p, const vtkHAVSFaceRasterizer::Ray& ray, size_t count, double& t0, double& t1)
  {
    t0 = parallel ? -VTK_DOUBLE_MAX : 0.0;
    t1 = VTK_DOUBLE_MAX;
    bool empty = false;
    for (size_t i = 0; i < count; ++i)
    {
      const WorldPlane& plane = planes[i];
      const double nd = vtkMath::Dot(plane.N, ray.Direction);
      const double c = vtkMath::Dot(plane.N, ray.Origin) + plane.W;
      if (nd > 0.0)
      {
        t0 = std::max(t0, -c / nd);
      }
      else if (nd < 0.0)
      {
        t1 = std::min(t1, -c / nd);
      }
      else if (c < 0.0)
      {
        empty = true;
      }
    }
    if (opaque && opaque[p] < 1.0f)
    {
      // The ray ends at the opaque surface.
      t1 = std::min(t1, rayAtDepth(p, ray, opaque[p]));
    }
    return !empty;
  };
  if (!planes.empty() || opaque)
  {
    // Each ray's interval [t0, t1] kept by the planes: fragments outside it
    // go; where it starts or ends inside the mesh, a synthetic entry or exit
    // fragment carries the mesh's scalar there.
    double worldBounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
      VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
    for (vtkIdType p = 0; p < numPoints; ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        worldBounds[2 * k] = std::min(worldBounds[2 * k], world[3 * p + k]);
        worldBounds[2 * k + 1] = std::max(worldBounds[2 * k + 1], world[3 * p + k]);
      }
    }
    double diagonal2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      diagonal2 += (worldBounds[2 * k + 1] - worldBounds[2 * k]) *
        (worldBounds[2 * k + 1] - worldBounds[2 * k]);
    }
    const double margin = 1e-9 * std::sqrt(diagonal2);
    // Rays can start inside the mesh only where a plane cuts its bounds (or
    // at an eye inside them): only then is the cell locator needed.
    bool needLocator = !parallel;
    for (int k = 0; k < 3; ++k)
    {
      needLocator = needLocator && eye[k] >= worldBounds[2 * k] - margin &&
        eye[k] <= worldBounds[2 * k + 1] + margin;
    }
    for (const WorldPlane& plane : planes)
    {
      const double equation[4] = { plane.N[0], plane.N[1], plane.N[2], plane.W };
      needLocator = needLocator || vtkHAVSPlaneSection::CutsBox(equation, worldBounds);
    }
    vtkNew<vtkStaticCellLocator> locator;
    if (needLocator)
    {
      locator->SetDataSet(this->Input);
      locator->BuildLocator();
    }
    vtkNew<vtkMatrix4x4> worldToModel;
    vtkMatrix4x4::Invert(this->VolumeMatrix, worldToModel);
    vtkUnstructuredGrid* grid = this->Input;

    std::vector<std::vector<Fragment>> clipped(static_cast<size_t>(pixels));
    std::vector<uint8_t> changed(static_cast<size_t>(pixels), 0);
    vtkSMPThreadLocal<vtkSmartPointer<vtkGenericCell>> localCell;
    vtkSMPThreadLocal<vtkIdType> localStarted(0);
    vtkSMPTools::For(0, pixels,
      [&](vtkIdType begin, vtkIdType end)
      {
        vtkSmartPointer<vtkGenericCell>& cell = localCell.Local();
        if (!cell)
        {
          cell = vtkSmartPointer<vtkGenericCell>::New();
        }
        vtkIdType& started = localStarted.Local();
        for (vtkIdType p = begin; p < end; ++p)
        {
          const vtkHAVSFaceRasterizer::Ray ray =
            rasterizer->GetPixelRay(static_cast<int>(p % width), static_cast<int>(p / width));
          double t0, t1;
          const bool empty = !keptInterval(p, ray, planes.size(), t0, t1);
          const Fragment* first = this->GetPixelFragmentsBegin(p);
          const Fragment* last = this->GetPixelFragmentsEnd(p);
          std::vector<Fragment>& out = clipped[p];
          if (empty || t0 >= t1)
          {
            changed[p] = first != last;
            continue;
          }
          const double d0 = ray.Offset + t0, d1 = ray.Offset + t1;

          // The mesh's scalar at ray parameter t, when a tetrahedron holds that point.
          auto scalarAt = [&](double t, double& scalar, float* gradient = nullptr)
          {
            double x[4] = { 0, 0, 0, 1 }, m[4];
            for (int k = 0; k < 3; ++k)
            {
              x[k] = ray.Origin[k] + t * ray.Direction[k];
            }
            bool inBounds = true;
            for (int k = 0; k < 3; ++k)
            {
              inBounds = inBounds && x[k] >= worldBounds[2 * k] - margin &&
                x[k] <= worldBounds[2 * k + 1] + margin;
            }
            if (!inBounds || !needLocator)
            {
              return false;
            }
            worldToModel->MultiplyPoint(x, m);
            double model[3] = { m[0] / m[3], m[1] / m[3], m[2] / m[3] };
            double pcoords[3], weights[8];
            int subId = 0;
            vtkIdType c = locator->FindCell(model, 0.0, cell, subId, pcoords, weights);
            if (c < 0 || grid->GetCellType(c) != VTK_TETRA)
            {
              return false;
            }
            // VTK's tetrahedron takes a point up to 1e-3 of its size outside
            // it as inside (EvaluatePosition): a ray that leaves the mesh just
            // before a plane would start inside at the plane and run on to
            // the next one with the last cell's value. The cell must hold the
            // point (barycentric weights >= -1e-7); else another near one
            // that does, or none: the point is outside the mesh.
            auto holds = [](const double* w)
            { return std::min(std::min(w[0], w[1]), std::min(w[2], w[3])) >= -1e-7; };
            if (!holds(weights))
            {
              c = -1;
              double box[6] = { model[0] - margin, model[0] + margin, model[1] - margin,
                model[1] + margin, model[2] - margin, model[2] + margin };
              vtkNew<vtkIdList> near;
              locator->FindCellsWithinBounds(box, near);
              for (vtkIdType i = 0; i < near->GetNumberOfIds() && c < 0; ++i)
              {
                const vtkIdType id = near->GetId(i);
                double closest[3], distance2;
                if (grid->GetCellType(id) == VTK_TETRA)
                {
                  grid->GetCell(id, cell);
                  if (cell->EvaluatePosition(model, closest, subId, pcoords, distance2, weights) ==
                      1 &&
                    holds(weights))
                  {
                    c = id;
                  }
                }
              }
              if (c < 0)
              {
                return false;
              }
            }
            scalar = 0.0;
            if (cellData)
            {
              scalar = values[c];
            }
            else
            {
              uint32_t ids[4];
              for (int i = 0; i < 4; ++i)
              {
                ids[i] = static_cast<uint32_t>(cell->GetPointId(i));
                scalar += weights[i] * values[ids[i]];
              }
              if (gradient && this->ShadeIsoSurfaces)
              {
                interpolateGradient(ids, weights, 4, gradient);
              }
            }
            return true;
          };
          // Does the ray start inside the mesh? The tetrahedron at the start point.
          double startScalar = 0.0;
          float startGradient[3] = { 0.0f, 0.0f, 0.0f };
          const bool startInside = t0 > -VTK_DOUBLE_MAX && scalarAt(t0, startScalar, startGradient);
          bool dropsSome = false;
          for (const Fragment* f = first; f != last && !dropsSome; ++f)
          {
            dropsSome = f->Distance <= d0 || f->Distance >= d1;
          }
          // A ray cut at t1 whose fragments end inside the mesh: the faces
          // beyond the plane were left out (wholly on the discarded side), and
          // the ray still ends at the plane.
          bool endsInside = false;
          if (t1 < VTK_DOUBLE_MAX && !dropsSome)
          {
            int boundaryHits = 0;
            for (const Fragment* f = first; f != last; ++f)
            {
              boundaryHits += f->Boundary ? 1 : 0;
            }
            endsInside = (boundaryHits % 2 == 1) != startInside;
          }
          if (!startInside && !dropsSome && !endsInside)
          {
            continue; // unchanged
          }
          changed[p] = 1;
          started += startInside ? 1 : 0;
          if (startInside)
          {
            out.push_back({ d0, startScalar, StartFace, true, false });
            std::copy_n(startGradient, 3, out.back().Gradient);
          }
          bool inside = startInside;
          const Fragment* f = first;
          while (f != last && f->Distance <= d0)
          {
            ++f;
          }
          while (f != last && f->Distance < d1)
          {
            const Fragment* next = f;
            int boundaryHits = 0;
            while (next != last && next->Distance == f->Distance)
            {
              boundaryHits += next->Boundary ? 1 : 0;
              out.push_back(*next);
              ++next;
            }
            inside = boundaryHits % 2 == 1 ? !inside : inside;
            f = next;
          }
          if (inside && t1 < VTK_DOUBLE_MAX && !out.empty())
          {
            const Fragment& previous = out.back();
            // (Cell scalars: both ends have the one cell's value.)
            const double from = previous.ScalarBehind();
            double scalar = from;
            float gradient[3];
            std::copy_n(previous.Gradient, 3, gradient);
            if (f != last && f->Distance > previous.Distance)
            {
              const double share = (d1 - previous.Distance) / (f->Distance - previous.Distance);
              scalar += (f->Scalar - from) * share;
              for (int k = 0; k < 3; ++k)
              {
                gradient[k] += static_cast<float>((f->Gradient[k] - gradient[k]) * share);
              }
            }
            else if (f == last)
            {
              // No fragment beyond (culled with its face): the mesh's value at the end.
              scalarAt(t1, scalar, gradient);
            }
            out.push_back({ d1, scalar, EndFace, true, true });
            std::copy_n(gradient, 3, out.back().Gradient);
          }
        }
      });
    for (vtkIdType started : localStarted)
    {
      this->NumberOfStartedInside += started;
    }
    std::vector<Fragment> fragments;
    std::vector<vtkIdType> start(static_cast<size_t>(pixels) + 1, 0);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      start[p + 1] = start[p] +
        (changed[p] ? static_cast<vtkIdType>(clipped[p].size())
                    : this->PixelStart[p + 1] - this->PixelStart[p]);
    }
    fragments.resize(start[pixels]);
    vtkSMPTools::For(0, pixels,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          if (changed[p])
          {
            std::copy(clipped[p].begin(), clipped[p].end(), fragments.begin() + start[p]);
          }
          else
          {
            std::copy(this->GetPixelFragmentsBegin(p), this->GetPixelFragmentsEnd(p),
              fragments.begin() + start[p]);
          }
        }
      });
    this->Fragments.swap(fragments);
    this->PixelStart.swap(start);
  }
  // The translucent layers' fragments and the surfaces' hits as events
  // along the rays, in depth order.
  std::vector<std::vector<SurfaceEvent>> events(static_cast<size_t>(pixels));
  for (const TranslucentLayer& layer : this->TranslucentLayers)
  {
    if (layer.Depth->GetNumberOfTuples() < pixels)
    {
      vtkErrorMacro("A translucent layer is smaller than the image: left out.");
      continue;
    }
    vtkSMPTools::For(0, pixels,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          const float z = layer.Depth->GetValue(p);
          if (z >= 1.0f)
          {
            continue;
          }
          const vtkHAVSFaceRasterizer::Ray ray =
            rasterizer->GetPixelRay(static_cast<int>(p % width), static_cast<int>(p / width));
          const float* c = layer.RGBA->GetPointer(4 * p);
          const double a = std::min(1.0, std::max(0.0, static_cast<double>(c[3])));
          SurfaceEvent e;
          e.Distance = ray.Offset + rayAtDepth(p, ray, z);
          e.RGBA[0] = a * c[0];
          e.RGBA[1] = a * c[1];
          e.RGBA[2] = a * c[2];
          e.RGBA[3] = a;
          events[p].push_back(e);
        }
      });
  }
  for (const TranslucentSurface& surface : this->TranslucentSurfaces)
  {
    // Its polygons as triangles (fans), in world coordinates.
    vtkPolyData* poly = surface.Surface;
    std::vector<double> points(3 * static_cast<size_t>(poly->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
      poly->GetPoint(i, &points[3 * i]);
    }
    std::vector<uint32_t> triangles;
    vtkCellArray* polys = poly->GetPolys();
    vtkNew<vtkIdList> ids;
    polys->InitTraversal();
    while (polys->GetNextCell(ids))
    {
      for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
      {
        triangles.push_back(static_cast<uint32_t>(ids->GetId(0)));
        triangles.push_back(static_cast<uint32_t>(ids->GetId(k)));
        triangles.push_back(static_cast<uint32_t>(ids->GetId(k + 1)));
      }
    }
    vtkNew<vtkHAVSFaceRasterizer> surfaceRasterizer;
    surfaceRasterizer->SetView(
      worldToClip->GetData(), eye, directionOfProjection, parallel, width, height);
    surfaceRasterizer->Rasterize(
      points, triangles.data(), static_cast<vtkIdType>(triangles.size() / 3));
    const std::vector<vtkIdType>& start = surfaceRasterizer->GetPixelStart();
    const std::vector<vtkHAVSFaceRasterizer::Hit>& hits = surfaceRasterizer->GetHits();
    const double a = std::min(1.0, std::max(0.0, surface.RGBA[3]));
    vtkSMPTools::For(0, pixels,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType p = begin; p < end; ++p)
        {
          const vtkHAVSFaceRasterizer::Ray ray =
            rasterizer->GetPixelRay(static_cast<int>(p % width), static_cast<int>(p / width));
          // In front of the near plane (the first plane; the volume's
          // clipping planes do not cut actors) or behind the opaque surface: not drawn.
          double t0, t1;
          if (!keptInterval(p, ray, this->NearPlaneClipping ? 1 : 0, t0, t1))
          {
            continue;
          }
          for (vtkIdType h = start[p]; h < start[p + 1]; ++h)
          {
            const double t = hits[h].Distance - ray.Offset;
            if (t < t0 || t > t1)
            {
              continue;
            }
            SurfaceEvent e;
            e.Distance = hits[h].Distance;
            for (int k = 0; k < 3; ++k)
            {
              e.RGBA[k] = a * surface.RGBA[k];
            }
            e.RGBA[3] = a;
            events[p].push_back(e);
          }
        }
      });
  }
  this->SurfaceEvents.clear();
  this->SurfaceEventStart.assign(static_cast<size_t>(pixels) + 1, 0);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    std::stable_sort(events[p].begin(), events[p].end(),
      [](const SurfaceEvent& x, const SurfaceEvent& y) { return x.Distance < y.Distance; });
    this->SurfaceEventStart[p + 1] =
      this->SurfaceEventStart[p] + static_cast<vtkIdType>(events[p].size());
    this->SurfaceEvents.insert(this->SurfaceEvents.end(), events[p].begin(), events[p].end());
  }
  this->ReportProgress(1.0);
  return true;
}

//------------------------------------------------------------------------------
namespace
{
/// Calls f(front, back) for each segment of the ray (its sorted fragments)
/// that lies in the mesh, by the parity of the boundary hits before it.
template <typename F>
void ForEachSegmentInMesh(const vtkHAVSReferenceRenderer::Fragment* begin,
  const vtkHAVSReferenceRenderer::Fragment* end, F&& f)
{
  bool inside = false;
  const vtkHAVSReferenceRenderer::Fragment* group = begin;
  while (group != end)
  {
    // Fragments at the same distance: a crossing of a shared edge or vertex
    // (once, by the tie-break), or a graze (an even number of boundary hits).
    const vtkHAVSReferenceRenderer::Fragment* next = group;
    int boundaryHits = 0;
    while (next != end && next->Distance == group->Distance)
    {
      boundaryHits += next->Boundary ? 1 : 0;
      ++next;
    }
    if (boundaryHits % 2 == 1)
    {
      inside = !inside;
    }
    if (inside && next != end)
    {
      f(*group, *next);
    }
    group = next;
  }
}

/// Premultiplied pieces composited front to back.
struct FrontToBack
{
  double Color[3] = { 0, 0, 0 };
  double Transmittance = 1.0;
  void Add(const double piece[4])
  {
    for (int c = 0; c < 3; ++c)
    {
      this->Color[c] += this->Transmittance * piece[c];
    }
    this->Transmittance *= 1.0 - piece[3];
  }
  void Get(double rgba[4]) const
  {
    std::copy_n(this->Color, 3, rgba);
    rgba[3] = 1.0 - this->Transmittance;
  }
};
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::IntegrateSegmentExact(
  vtkVolumeProperty* property, double sf, double sb, double length, double rgba[4])
{
  // Split at every node of the opacity and colour functions between sf and sb.
  std::vector<double> cuts = { 0.0, 1.0 };
  if (sf != sb)
  {
    const double lo = std::min(sf, sb), hi = std::max(sf, sb);
    std::vector<double> nodes;
    vtkHAVSPreIntegrationTable::GetFunctionNodes(property, 0, nodes);
    for (double x : nodes)
    {
      if (x > lo && x < hi)
      {
        cuts.push_back((x - sf) / (sb - sf));
      }
    }
    std::sort(cuts.begin(), cuts.end());
  }
  FrontToBack composite;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double a = cuts[i], b = cuts[i + 1];
    if (b <= a)
    {
      continue;
    }
    double piece[4];
    vtkHAVSPreIntegrationTable::IntegrateSegment(
      property, 0, sf + (sb - sf) * a, sf + (sb - sf) * b, length * (b - a), piece);
    composite.Add(piece);
  }
  composite.Get(rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::IntegrateRay(
  vtkVolumeProperty* property, const Fragment* begin, const Fragment* end, double rgba[4])
{
  FrontToBack composite;
  ForEachSegmentInMesh(begin, end,
    [&](const Fragment& front, const Fragment& back)
    {
      double segment[4];
      IntegrateSegmentExact(
        property, front.ScalarBehind(), back.Scalar, back.Distance - front.Distance, segment);
      composite.Add(segment);
    });
  composite.Get(rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::IntegrateRayWithSurfaces(vtkVolumeProperty* property,
  const Fragment* begin, const Fragment* end, const SurfaceEvent* eventsBegin,
  const SurfaceEvent* eventsEnd, double rgba[4], const vtkHAVSIsoSurfaces* iso, const double* toEye)
{
  FrontToBack composite;
  const bool shaded = iso && iso->Shaded && toEye;
  // The segment's ends' gradients (shaded isosurfaces: a crossing at share u
  // of the segment has their mix).
  const float* gradientFrom = nullptr;
  const float* gradientTo = nullptr;
  // A piece of a segment (scalar sf -> sb linear) from share uFrom to uTo of
  // it: the volume, or with isosurfaces their crossings (and, in the mixed
  // mode, the volume between).
  auto addPiece = [&](double sf, double sb, double length, double uFrom, double uTo)
  {
    double piece[4];
    if (!iso)
    {
      IntegrateSegmentExact(property, sf, sb, length, piece);
      composite.Add(piece);
      return;
    }
    double from = 0.0, sFrom = sf;
    for (int i : iso->Crossed(sf, sb))
    {
      const double v = iso->Values[i];
      if (iso->Composite)
      {
        const double t = (v - sf) / (sb - sf);
        IntegrateSegmentExact(property, sFrom, v, length * (t - from), piece);
        composite.Add(piece);
        from = t;
        sFrom = v;
      }
      if (shaded && gradientFrom && gradientTo)
      {
        const double u = uFrom + (uTo - uFrom) * (v - sf) / (sb - sf);
        double gradient[3], lit[4];
        for (int k = 0; k < 3; ++k)
        {
          gradient[k] = gradientFrom[k] + u * (gradientTo[k] - gradientFrom[k]);
        }
        iso->Shade(iso->Colors[i], gradient, toEye, lit);
        composite.Add(lit);
      }
      else
      {
        composite.Add(iso->Colors[i]); // (the surface's colour, SurfaceColor at Make)
      }
    }
    if (iso->Composite)
    {
      IntegrateSegmentExact(property, sFrom, sb, length * (1.0 - from), piece);
      composite.Add(piece);
    }
  };
  const SurfaceEvent* e = eventsBegin;
  ForEachSegmentInMesh(begin, end,
    [&](const Fragment& front, const Fragment& back)
    {
      // Surfaces in front of the segment, then the segment split at those inside it.
      for (; e != eventsEnd && e->Distance <= front.Distance; ++e)
      {
        composite.Add(e->RGBA);
      }
      const double sf = front.ScalarBehind(), sb = back.Scalar;
      const double length = back.Distance - front.Distance;
      gradientFrom = front.Gradient;
      gradientTo = back.Gradient;
      double from = 0.0; // the piece's start, as a share of the segment
      for (; e != eventsEnd && e->Distance < back.Distance; ++e)
      {
        const double to = length > 0.0 ? (e->Distance - front.Distance) / length : 0.0;
        addPiece(sf + (sb - sf) * from, sf + (sb - sf) * to, length * (to - from), from, to);
        composite.Add(e->RGBA);
        from = to;
      }
      addPiece(sf + (sb - sf) * from, sb, length * (1.0 - from), from, 1.0);
    });
  for (; e != eventsEnd; ++e)
  {
    composite.Add(e->RGBA);
  }
  composite.Get(rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::IntegrateRayBlend(vtkVolumeProperty* property, const Fragment* begin,
  const Fragment* end, int blendMode, const double scalarRange[2], double rgba[4])
{
  const bool maximum = blendMode == 1, minimum = blendMode == 2, additive = blendMode == 4;
  if (!maximum && !minimum && !additive)
  {
    IntegrateRay(property, begin, end, rgba);
    return;
  }
  bool covered = false;
  double extremum = 0.0, sum = 0.0;
  ForEachSegmentInMesh(begin, end,
    [&](const Fragment& front, const Fragment& back)
    {
      if (additive)
      {
        sum += IntegrateAdditiveSegment(
          property, front.ScalarBehind(), back.Scalar, back.Distance - front.Distance, scalarRange);
      }
      else
      {
        for (double s : { front.ScalarBehind(), back.Scalar })
        {
          extremum = !covered ? s : (maximum ? std::max(extremum, s) : std::min(extremum, s));
          covered = true;
        }
      }
      covered = true;
    });
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  if (!covered)
  {
    return;
  }
  if (additive)
  {
    rgba[0] = rgba[1] = rgba[2] = std::min(1.0, std::max(0.0, sum));
    rgba[3] = 1.0;
    return;
  }
  // The colour of the extremal scalar, as the mappers look it up (clamped to the range).
  const double s = std::min(std::max(extremum, scalarRange[0]), scalarRange[1]);
  double color[3];
  vtkHAVSPreIntegrationTable::EvaluateColor(property, 0, s, color);
  const double a = std::max(0.0, property->GetScalarOpacity(0)->GetValue(s));
  for (int c = 0; c < 3; ++c)
  {
    rgba[c] = color[c] * a;
  }
  rgba[3] = a;
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::IntegrateRayIso(vtkVolumeProperty* property, const Fragment* begin,
  const Fragment* end, const vtkHAVSIsoSurfaces& iso, double rgba[4], const double* toEye)
{
  IntegrateRayWithSurfaces(property, begin, end, nullptr, nullptr, rgba, &iso, toEye);
}

//------------------------------------------------------------------------------
double vtkHAVSReferenceRenderer::IntegrateAdditiveSegment(
  vtkVolumeProperty* property, double sf, double sb, double length, const double scalarRange[2])
{
  if (!(length > 0.0))
  {
    return 0.0;
  }
  const double span = scalarRange[1] - scalarRange[0];
  const double unit = property->GetScalarOpacityUnitDistance(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  // The integrand along the segment's parameter u in [0, 1].
  auto g = [&](double u)
  {
    const double s = sf + (sb - sf) * u;
    const double normalized = span > 0.0 ? (s - scalarRange[0]) / span : 0.0;
    return std::max(0.0, opacity->GetValue(s)) / unit * normalized;
  };
  std::vector<double> cuts = { 0.0, 1.0 };
  if (sf != sb)
  {
    // (The colour nodes too: extra cuts where the integrand is smooth cost nothing.)
    std::vector<double> nodes;
    vtkHAVSPreIntegrationTable::GetFunctionNodes(property, 0, nodes);
    for (double x : nodes)
    {
      const double u = (x - sf) / (sb - sf);
      if (u > 0.0 && u < 1.0)
      {
        cuts.push_back(u);
      }
    }
    std::sort(cuts.begin(), cuts.end());
  }
  // Adaptive Simpson on each piece.
  std::function<double(double, double, double, double, double, double, double, int)> simpson;
  simpson = [&](double a, double b, double fa, double fm, double fb, double whole, double tolerance,
              int depth) -> double
  {
    const double m = 0.5 * (a + b);
    const double lm = g(0.5 * (a + m)), rm = g(0.5 * (m + b));
    const double left = (m - a) / 6.0 * (fa + 4.0 * lm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * rm + fb);
    if (depth <= 0 || std::fabs(left + right - whole) <= 15.0 * tolerance)
    {
      return left + right + (left + right - whole) / 15.0;
    }
    return simpson(a, m, fa, lm, fm, left, 0.5 * tolerance, depth - 1) +
      simpson(m, b, fm, rm, fb, right, 0.5 * tolerance, depth - 1);
  };
  double integral = 0.0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double a = cuts[i], b = cuts[i + 1];
    if (b <= a)
    {
      continue;
    }
    const double fa = g(a), fm = g(0.5 * (a + b)), fb = g(b);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    integral += simpson(a, b, fa, fm, fb, whole, 1e-9 * (b - a), 24);
  }
  return integral * length;
}

//------------------------------------------------------------------------------
bool vtkHAVSReferenceRenderer::Render()
{
  if (!this->Property)
  {
    vtkErrorMacro("No volume property.");
    return false;
  }
  // Progress: the fragments are the first tenth of the work, the
  // integration (in 20 slices of pixels) the rest.
  this->ProgressRange[0] = 0.0;
  this->ProgressRange[1] = 0.1;
  const bool fragments = this->ComputeFragments();
  this->ProgressRange[0] = 0.0;
  this->ProgressRange[1] = 1.0;
  if (!fragments)
  {
    return false;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(this->Size[0]) * this->Size[1];
  this->Image->SetNumberOfComponents(4);
  this->Image->SetNumberOfTuples(pixels);
  float* out = this->Image->GetPointer(0);
  // VTK's function objects are not promised to be thread-safe: one copy of
  // the property per thread, made one at a time (DeepCopy creates missing
  // functions in the source).
  vtkSMPThreadLocal<vtkSmartPointer<vtkVolumeProperty>> localProperty;
  // The isosurfaces (the isosurface blend, or the composite's mixed mode).
  vtkHAVSIsoSurfaces iso = vtkHAVSIsoSurfaces::Make(
    this->Property, this->BlendMode, this->IsoSurfacesInComposite, this->ScalarRange);
  if (this->ShadeIsoSurfaces)
  {
    // (The gradients are world's already: no normal matrix.)
    iso.MakeShading(this->Property, 0, this->Lights, nullptr);
  }
  const bool shaded = iso.Shaded && !this->PixelDirections.empty();
  const bool isoRay = this->BlendMode == vtkHAVSIsoSurfaces::IsoSurfaceBlend || iso.Count > 0;
  // Translucent layers: under the blends composited front to back (composite, isosurface).
  const bool frontToBack = this->BlendMode != 1 && this->BlendMode != 2 && this->BlendMode != 4;
  const bool surfaces =
    (!this->TranslucentLayers.empty() || !this->TranslucentSurfaces.empty()) && frontToBack;
  std::mutex copying;
  const vtkIdType slices = 20;
  for (vtkIdType slice = 0; slice < slices; ++slice)
  {
    vtkSMPTools::For(slice * pixels / slices, (slice + 1) * pixels / slices,
      [&](vtkIdType begin, vtkIdType end)
      {
        vtkSmartPointer<vtkVolumeProperty>& property = localProperty.Local();
        if (!property)
        {
          std::lock_guard<std::mutex> lock(copying);
          property = vtkSmartPointer<vtkVolumeProperty>::New();
          property->DeepCopy(this->Property);
        }
        for (vtkIdType p = begin; p < end; ++p)
        {
          double rgba[4];
          double toEye[3] = { 0.0, 0.0, 1.0 };
          if (shaded)
          {
            for (int k = 0; k < 3; ++k)
            {
              toEye[k] = -this->PixelDirections[3 * static_cast<size_t>(p) + k];
            }
          }
          if (surfaces)
          {
            IntegrateRayWithSurfaces(property, this->GetPixelFragmentsBegin(p),
              this->GetPixelFragmentsEnd(p),
              this->SurfaceEvents.data() + this->SurfaceEventStart[p],
              this->SurfaceEvents.data() + this->SurfaceEventStart[p + 1], rgba,
              isoRay ? &iso : nullptr, shaded ? toEye : nullptr);
          }
          else if (isoRay)
          {
            IntegrateRayIso(property, this->GetPixelFragmentsBegin(p),
              this->GetPixelFragmentsEnd(p), iso, rgba, shaded ? toEye : nullptr);
          }
          else
          {
            IntegrateRayBlend(property, this->GetPixelFragmentsBegin(p),
              this->GetPixelFragmentsEnd(p), this->BlendMode, this->ScalarRange, rgba);
          }
          for (int c = 0; c < 4; ++c)
          {
            out[4 * p + c] = static_cast<float>(rgba[c]);
          }
        }
      });
    this->ReportProgress(0.1 + 0.9 * static_cast<double>(slice + 1) / slices);
  }
  this->Image->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Fragments: " << this->Fragments.size() << "\n";
  os << indent << "HigherOrderSubdivision: " << this->HigherOrderSubdivision << "\n";
  os << indent << "NearPlaneClipping: " << this->NearPlaneClipping
     << ", BlendMode: " << this->BlendMode
     << ", IsoSurfacesInComposite: " << this->IsoSurfacesInComposite << "\n";
  os << indent
     << "ClippingPlanes: " << (this->ClippingPlanes ? this->ClippingPlanes->GetNumberOfItems() : 0)
     << "\n";
  os << indent << "OpaqueDepth: " << (this->OpaqueDepth ? "set" : "none") << "\n";
  os << indent << "TranslucentLayers: " << this->TranslucentLayers.size()
     << ", TranslucentSurfaces: " << this->TranslucentSurfaces.size() << "\n";
  os << indent << "NumberOfStartedInside: " << this->NumberOfStartedInside << "\n";
}

VTK_ABI_NAMESPACE_END
