/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSMesh.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkHAVSFaceSet.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkHAVSMesh);

namespace
{
/// As vtkAbstractVolumeMapper::GetScalarModeAsString.
const char* ScalarModeName(int mode)
{
  switch (mode)
  {
    case VTK_SCALAR_MODE_USE_POINT_DATA:
      return "PointData";
    case VTK_SCALAR_MODE_USE_CELL_DATA:
      return "CellData";
    case VTK_SCALAR_MODE_USE_POINT_FIELD_DATA:
      return "PointFieldData";
    case VTK_SCALAR_MODE_USE_CELL_FIELD_DATA:
      return "CellFieldData";
    case VTK_SCALAR_MODE_USE_FIELD_DATA:
      return "FieldData";
    default:
      return "Default";
  }
}
}

vtkHAVSMesh::vtkHAVSMesh() = default;
vtkHAVSMesh::~vtkHAVSMesh() = default;

//------------------------------------------------------------------------------
bool vtkHAVSMesh::NeedsBuild(vtkDataObject* input, const ScalarSelection& selection) const
{
  return !this->BuildTime.GetMTime() || input != this->BuiltInput ||
    (input && input->GetMTime() > this->BuiltInputTime) || !(selection == this->BuiltSelection);
}

//------------------------------------------------------------------------------
bool vtkHAVSMesh::Fail(const std::string& why)
{
  this->Error = why;
  this->Valid = false;
  return false;
}

//------------------------------------------------------------------------------
bool vtkHAVSMesh::Build(vtkDataObject* input, const ScalarSelection& selection,
  const std::function<void(double)>& progress)
{
  this->BuiltInput = input;
  this->BuiltInputTime = input ? input->GetMTime() : 0;
  this->BuiltSelection = selection;
  this->BuildTime.Modified();
  this->Valid = false;
  this->Error.clear();
  this->Warnings.clear();
  auto report = [&](double p)
  {
    if (progress)
    {
      progress(p);
    }
  };

  if (!input)
  {
    return this->Fail("No input.");
  }
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(input);
  if (!grid)
  {
    return this->Fail(std::string("The input is a ") + input->GetClassName() +
      "; vtkHAVSVolumeMapper needs a vtkUnstructuredGrid.");
  }
  if (grid->GetNumberOfPoints() == 0 || grid->GetNumberOfCells() == 0)
  {
    std::ostringstream why;
    why << "The input grid is empty (" << grid->GetNumberOfPoints() << " points, "
        << grid->GetNumberOfCells() << " cells).";
    return this->Fail(why.str());
  }

  int cellFlag = -1;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(grid, selection.Mode, selection.AccessMode,
    selection.Id, selection.Name.empty() ? nullptr : selection.Name.c_str(), cellFlag);
  if (!scalars)
  {
    std::ostringstream why;
    why << "The input has no scalars to render (scalar mode " << ScalarModeName(selection.Mode)
        << (selection.Name.empty() ? "" : ", array " + selection.Name) << ").";
    return this->Fail(why.str());
  }
  if (cellFlag != 0)
  {
    return this->Fail("Cell scalars are not supported by vtkHAVSVolumeMapper yet; use point "
                      "scalars (e.g. vtkCellDataToPointData).");
  }

  report(0.0);
  if (!this->Faces->Build(grid))
  {
    return this->Fail("No tetrahedra to render in the input.");
  }
  report(0.6);
  if (this->Faces->GetNumberOfSkippedCells() > 0)
  {
    std::ostringstream w;
    w << this->Faces->GetNumberOfSkippedCells()
      << " cells that are not tetrahedra were skipped (tetrahedralize the input, e.g. with "
         "vtkDataSetTriangleFilter).";
    this->Warnings.push_back(w.str());
  }
  if (this->Faces->GetNumberOfDegenerateTetrahedra() > 0)
  {
    std::ostringstream w;
    w << this->Faces->GetNumberOfDegenerateTetrahedra()
      << " degenerate (zero-volume) tetrahedra were dropped.";
    this->Warnings.push_back(w.str());
  }
  if (this->Faces->GetNumberOfDuplicateTetrahedra() > 0)
  {
    std::ostringstream w;
    w << this->Faces->GetNumberOfDuplicateTetrahedra()
      << " duplicate tetrahedra (the same four points as another cell) were dropped; one copy "
         "of each is drawn.";
    this->Warnings.push_back(w.str());
  }

  // Independent components are rendered from the first one.
  this->NumberOfComponents = scalars->GetNumberOfComponents();
  this->Component = 0;

  // Points, shifted by the bounds' centre so that floats keep their precision.
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  double bounds[6];
  grid->GetPoints()->GetBounds(bounds);
  for (int i = 0; i < 3; ++i)
  {
    this->Shift[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
    this->Bounds[2 * i] = bounds[2 * i] - this->Shift[i];
    this->Bounds[2 * i + 1] = bounds[2 * i + 1] - this->Shift[i];
  }
  this->Points.resize(3 * numPoints);
  vtkIdType nonFinitePoints = 0;
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double x[3];
    grid->GetPoint(p, x);
    for (int i = 0; i < 3; ++i)
    {
      double v = x[i] - this->Shift[i];
      if (!std::isfinite(v))
      {
        ++nonFinitePoints;
        v = 0.0;
      }
      this->Points[3 * p + i] = static_cast<float>(v);
    }
  }
  if (nonFinitePoints > 0)
  {
    std::ostringstream why;
    why << nonFinitePoints << " non-finite point coordinates; the mesh is not rendered.";
    return this->Fail(why.str());
  }

  // Scalars mapped to [0, 1] over the finite range of the points the cells
  // use (an unused point's value changes nothing); NaN/Inf replaced.
  const std::vector<uint8_t> used = this->Faces->GetPointUse(numPoints);
  double range[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
  vtkIdType nonFinite = 0;
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    if (!used[p])
    {
      continue;
    }
    const double s = scalars->GetComponent(p, this->Component);
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
    return this->Fail("Every scalar value is NaN or infinite; nothing to render.");
  }
  if (nonFinite > 0)
  {
    std::ostringstream w;
    w << nonFinite << " NaN/infinite scalar values were replaced by the lowest finite value ("
      << range[0] << ").";
    this->Warnings.push_back(w.str());
  }
  this->ScalarRange[0] = range[0];
  this->ScalarRange[1] = range[1];
  const double span = range[1] - range[0];
  this->Scalars.resize(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    double s = scalars->GetComponent(p, this->Component);
    if (!std::isfinite(s))
    {
      s = range[0];
    }
    this->Scalars[p] = span > 0.0 ? static_cast<float>((s - range[0]) / span) : 0.0f;
  }
  report(1.0);
  this->Valid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Valid: " << this->Valid << (this->Error.empty() ? "" : " (" + this->Error + ")")
     << "\n";
  os << indent << "Points: " << this->Points.size() / 3 << ", faces "
     << this->Faces->GetNumberOfFaces() << " (" << this->Faces->GetNumberOfBoundaryFaces()
     << " boundary)\n";
  os << indent << "Shift: " << this->Shift[0] << " " << this->Shift[1] << " " << this->Shift[2]
     << "\n";
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1]
     << " (component " << this->Component << " of " << this->NumberOfComponents << ")\n";
}
