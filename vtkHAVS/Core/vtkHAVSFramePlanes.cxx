/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFramePlanes.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSFramePlanes.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPlaneSection.h"
#include "vtkHAVSViewFrame.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkTimerLog.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSFramePlanes);

vtkHAVSFramePlanes::vtkHAVSFramePlanes() = default;
vtkHAVSFramePlanes::~vtkHAVSFramePlanes() = default;

//------------------------------------------------------------------------------
bool vtkHAVSFramePlanes::Update(
  const vtkHAVSViewFrame& view, vtkPlaneCollection* clipping, vtkHAVSMesh* mesh, bool sections)
{
  // Planes in eye-relative world coordinates (x_RC = world - eye), kept where
  // dot(n, x_RC) + w >= 0, with whether the rays enter the kept side there.
  struct Candidate
  {
    double Equation[4];
    bool Entering;
  };
  std::vector<Candidate> candidates;
  const double* eye = view.EyeWorld;
  const double* direction = view.DirectionWorld;

  // The near plane, a hair beyond the camera's (GL clips there; the section
  // must lie just inside): only when it cuts the mesh's bounds.
  const double nearDepth =
    view.ClippingRange[0] + 1e-5 * (view.ClippingRange[1] - view.ClippingRange[0]);
  candidates.push_back({ { direction[0], direction[1], direction[2], -nearDepth }, true });

  const int userPlanes = clipping ? clipping->GetNumberOfItems() : 0;
  for (int i = 0; i < std::min(userPlanes, MaximumClippingPlanes); ++i)
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
    const bool entering = view.Parallel ? vtkMath::Dot(n, direction) > 0.0 : w < 0.0;
    candidates.push_back({ { n[0], n[1], n[2], w }, entering });
  }

  // Each plane in model coordinates: the sections are cut there.
  const double* bounds = mesh->GetBounds();
  const double* m = view.ModelToEyeRelative;
  this->Planes.clear();
  this->ModelPlanes.clear();
  this->NearPlaneCutsMesh = false;
  std::vector<Cut> cuts;
  for (const Candidate& candidate : candidates)
  {
    const bool nearPlane = &candidate == &candidates.front();
    double planeModel[4];
    for (int c = 0; c < 4; ++c)
    {
      planeModel[c] = 0.0;
      for (int r = 0; r < 3; ++r)
      {
        planeModel[c] += candidate.Equation[r] * m[4 * r + c];
      }
    }
    planeModel[3] += candidate.Equation[3];
    const bool cutsMesh = vtkHAVSPlaneSection::CutsBox(planeModel, bounds);
    const double corner[3] = { bounds[0], bounds[2], bounds[4] };
    const bool allDiscarded = !cutsMesh &&
      planeModel[0] * corner[0] + planeModel[1] * corner[1] + planeModel[2] * corner[2] +
          planeModel[3] <
        0.0;
    if (!cutsMesh && !allDiscarded)
    {
      continue; // the whole mesh is kept: the plane changes nothing
    }
    this->NearPlaneCutsMesh = this->NearPlaneCutsMesh || nearPlane;
    const int index = static_cast<int>(this->Planes.size());
    this->Planes.push_back(
      { static_cast<float>(candidate.Equation[0]), static_cast<float>(candidate.Equation[1]),
        static_cast<float>(candidate.Equation[2]), static_cast<float>(candidate.Equation[3]) });
    this->ModelPlanes.push_back({ planeModel[0], planeModel[1], planeModel[2], planeModel[3] });
    if (cutsMesh && sections && (nearPlane || !this->NearPlaneSectionsOnly))
    {
      cuts.push_back({ index, candidate.Entering,
        { planeModel[0], planeModel[1], planeModel[2], planeModel[3] } });
    }
  }

  // Sections, only when a cut plane or the mesh changed.
  // (The scalar time: a new time step's sections carry its scalars.)
  const vtkMTimeType meshTime = std::max(mesh->GetBuildTime(), mesh->GetScalarTime());
  if (!(cuts == this->Cuts) || this->CutsMeshTime != meshTime)
  {
    const double start = vtkTimerLog::GetUniversalTime();
    this->Cuts = cuts;
    this->CutsMeshTime = meshTime;
    this->Sections.clear();
    this->SectionTriangles = 0;
    for (const Cut& cut : cuts)
    {
      Section section;
      section.PlaneIndex = cut.Index;
      section.Entering = cut.Entering;
      this->SectionTriangles += this->Sectioner->Compute(mesh->GetFaceSet()->GetTetrahedra(),
        mesh->GetPoints(), mesh->GetScalars(), cut.PlaneModel.data(), section.Points,
        section.Scalars, &section.Cells);
      if (mesh->HasCellScalars())
      {
        // A section triangle lies in one tetrahedron: its cell's code.
        const std::vector<float>& cellCodes = mesh->GetTetrahedronCodes();
        for (size_t t = 0; t < section.Cells.size(); ++t)
        {
          std::fill_n(&section.Scalars[3 * t], 3, cellCodes[section.Cells[t]]);
        }
      }
      this->Sections.push_back(std::move(section));
    }
    this->SectionSeconds = vtkTimerLog::GetUniversalTime() - start;
    this->SectionsTime.Modified();
  }
  return userPlanes <= MaximumClippingPlanes;
}

//------------------------------------------------------------------------------
void vtkHAVSFramePlanes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Planes: " << this->Planes.size() << ", sections " << this->Sections.size()
     << " (" << this->SectionTriangles << " triangles, " << this->SectionSeconds << " s)\n";
}

VTK_ABI_NAMESPACE_END
