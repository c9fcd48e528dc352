/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMesh.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSMesh.h"

#include "vtkHAVSCellOptics.h"
#include "vtkHAVSVTKCompat.h"

#include "vtkAbstractMapper.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkHAVSFaceSet.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkStructuredGrid.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSMesh);

namespace
{
/// The warning for cells whose point ids fall outside the points (skipped
/// before the split, or by the face set).
std::string InvalidCellsWarning(vtkIdType cells)
{
  std::ostringstream w;
  w << cells
    << " cells refer to points that do not exist (a point id below 0 or past the last "
       "point) and were skipped.";
  return w.str();
}

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
double vtkHAVSMesh::ScalarOf(vtkDataArray* array, vtkIdType i) const
{
  const int components = array->GetNumberOfComponents();
  if (this->VectorMode == VectorModeMagnitude && components > 1)
  {
    double sum = 0.0;
    for (int c = 0; c < components; ++c)
    {
      const double v = array->GetComponent(i, c);
      sum += v * v;
    }
    return std::sqrt(sum);
  }
  const int c = this->VectorMode == VectorModeComponent
    ? std::min(std::max(this->VectorComponent, 0), components - 1)
    : 0;
  return array->GetComponent(i, c);
}

//------------------------------------------------------------------------------
uint64_t vtkHAVSMesh::GeometryHashOf(vtkDataSet* data)
{
  // FNV-1a over 64-bit words: the type, the counts, every coordinate's bits,
  // the cells' types and point ids, and the ghost flags.
  uint64_t h = 1469598103934665603ull;
  auto mix = [&h](uint64_t v)
  {
    h ^= v;
    h *= 1099511628211ull;
  };
  auto mixDouble = [&mix](double v)
  {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof(bits));
    mix(bits);
  };
  auto mixArray = [&](vtkDataArray* array)
  {
    if (!array)
    {
      mix(0);
      return;
    }
    const vtkIdType n = array->GetNumberOfValues();
    mix(static_cast<uint64_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      mixDouble(array->GetComponent(
        i / array->GetNumberOfComponents(), static_cast<int>(i % array->GetNumberOfComponents())));
    }
  };
  mix(static_cast<uint64_t>(data->GetDataObjectType()));
  mix(static_cast<uint64_t>(data->GetNumberOfPoints()));
  mix(static_cast<uint64_t>(data->GetNumberOfCells()));
  if (auto* pointSet = vtkPointSet::SafeDownCast(data))
  {
    mixArray(pointSet->GetPoints() ? pointSet->GetPoints()->GetData() : nullptr);
  }
  else
  {
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      double x[3];
      data->GetPoint(i, x);
      mixDouble(x[0]);
      mixDouble(x[1]);
      mixDouble(x[2]);
    }
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    mixArray(grid->GetCells() ? grid->GetCells()->GetConnectivityArray() : nullptr);
    mixArray(grid->GetCells() ? grid->GetCells()->GetOffsetsArray() : nullptr);
    mixArray(havs_vtk::CellTypeArray(grid));
  }
  else if (!vtkStructuredGrid::SafeDownCast(data) && !vtkImageData::SafeDownCast(data) &&
    !vtkRectilinearGrid::SafeDownCast(data))
  {
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
    {
      mix(static_cast<uint64_t>(data->GetCellType(c)));
      data->GetCellPoints(c, ids);
      for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
      {
        mix(static_cast<uint64_t>(ids->GetId(i)));
      }
    }
  }
  // (A structured grid's cells follow from its counts and dimensions.)
  if (auto* structured = vtkStructuredGrid::SafeDownCast(data))
  {
    int dims[3];
    structured->GetDimensions(dims);
    mix(static_cast<uint64_t>(dims[0]) | (static_cast<uint64_t>(dims[1]) << 21) |
      (static_cast<uint64_t>(dims[2]) << 42));
  }
  mixArray(data->GetCellGhostArray());
  return h;
}

//------------------------------------------------------------------------------
double vtkHAVSMesh::GetDiagonal() const
{
  const double* b = this->Bounds;
  return std::sqrt(
    (b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

//------------------------------------------------------------------------------
vtkUnstructuredGrid* vtkHAVSMesh::GetGrid()
{
  return this->Grid;
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkHAVSMesh::GetVertexPoints() const
{
  return this->CellScalars ? this->FaceVertexPoints : this->Points;
}

//------------------------------------------------------------------------------
const std::vector<float>& vtkHAVSMesh::GetVertexScalars() const
{
  return this->CellScalars ? this->FaceVertexScalars : this->Scalars;
}

//------------------------------------------------------------------------------
const std::vector<uint32_t>& vtkHAVSMesh::GetFaceVertexIds() const
{
  return this->CellScalars ? this->FaceVertexIds : this->Faces->GetFaceVertices();
}

//------------------------------------------------------------------------------
void vtkHAVSMesh::BuildCellScalarVertices(const std::vector<float>& cellCodes)
{
  const std::vector<uint32_t>& faces = this->Faces->GetFaceVertices();
  const std::vector<uint32_t>& sides = this->Faces->GetFaceCells();
  const vtkIdType numberOfFaces = this->Faces->GetNumberOfFaces();
  this->FaceVertexPoints.resize(9 * static_cast<size_t>(numberOfFaces));
  this->FaceVertexScalars.resize(6 * static_cast<size_t>(numberOfFaces));
  this->FaceVertexIds.resize(3 * static_cast<size_t>(numberOfFaces));
  vtkSMPTools::For(0, numberOfFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        // A boundary face has one cell: its code on both sides (the side
        // outside is never composited; the extremum blends see the cell).
        const uint32_t front = sides[2 * f], back = sides[2 * f + 1];
        const float normalSide = cellCodes[front != vtkHAVSFaceSet::NoCell ? front : back];
        const float otherSide = cellCodes[back != vtkHAVSFaceSet::NoCell ? back : front];
        for (int v = 0; v < 3; ++v)
        {
          const size_t vertex = 3 * static_cast<size_t>(f) + v;
          std::copy_n(&this->Points[3 * static_cast<size_t>(faces[vertex])], 3,
            &this->FaceVertexPoints[3 * vertex]);
          this->FaceVertexScalars[2 * vertex] = normalSide;
          this->FaceVertexScalars[2 * vertex + 1] = otherSide;
          this->FaceVertexIds[vertex] = static_cast<uint32_t>(vertex);
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkHAVSMesh::BuildCellValueCodes(
  const std::vector<double>& values, const std::vector<uint8_t>& used, std::vector<float>& codes)
{
  const size_t n = values.size();
  std::vector<double>& distinct = this->CellValues;
  distinct.clear();
  for (size_t i = 0; i < n; ++i)
  {
    if (used[i])
    {
      distinct.push_back(values[i]);
    }
  }
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  // More distinct values than codes: the values rounded to a grid of
  // MaximumValues nodes over the range (steps of 4.8e-7 of it). `drawn` is a
  // value as it is drawn: rounded or itself.
  const bool rounded = distinct.size() > vtkHAVSCellOptics::MaximumValues;
  const double lo = this->ScalarRange[0], span = this->ScalarRange[1] - this->ScalarRange[0];
  const double steps = vtkHAVSCellOptics::MaximumValues - 1;
  auto drawn = [&](double v)
  {
    return rounded
      ? lo + std::min(std::max(std::round((v - lo) / span * steps), 0.0), steps) / steps * span
      : v;
  };
  if (rounded)
  {
    std::ostringstream w;
    w << distinct.size() << " distinct cell values: more than the "
      << vtkHAVSCellOptics::MaximumValues
      << " the passes tell apart; each is rounded to the nearest of that many evenly spaced "
         "values over the range (a step of "
      << span / steps << ").";
    this->Warnings.push_back(w.str());
    for (double& v : distinct)
    {
      v = drawn(v);
    }
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (!used[i])
        {
          continue;
        }
        const auto at = std::lower_bound(distinct.begin(), distinct.end(), drawn(values[i]));
        codes[i] = vtkHAVSCellOptics::CodeOf(static_cast<uint32_t>(at - distinct.begin()));
      }
    });
}

//------------------------------------------------------------------------------
bool vtkHAVSMesh::MapScalars(vtkDataArray* scalars, bool cellData, const std::string& arrayName)
{
  // The scalar rendered: the property's component 0 colours it.
  this->NumberOfComponents = scalars->GetNumberOfComponents();
  this->Component = 0;
  {
    std::ostringstream d;
    d << (cellData ? "cell" : "point") << " array '" << arrayName << "'";
    if (this->NumberOfComponents > 1)
    {
      if (this->VectorMode == VectorModeMagnitude)
      {
        d << ", the magnitude of its " << this->NumberOfComponents << " components";
      }
      else
      {
        const int c = this->VectorMode == VectorModeComponent
          ? std::min(std::max(this->VectorComponent, 0), this->NumberOfComponents - 1)
          : 0;
        d << ", component " << c << " of " << this->NumberOfComponents;
      }
    }
    this->ScalarDescription = d.str();
  }

  vtkUnstructuredGrid* grid = this->Grid;
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  // Scalars mapped to [0, 1] over the finite range of the values the used
  // cells see (an unused point's or dropped cell's value changes nothing);
  // NaN/Inf replaced.
  const std::vector<uint32_t>& tetCells = this->Faces->GetTetrahedronCells();
  std::vector<uint8_t> used;
  const vtkIdType numValues = cellData ? grid->GetNumberOfCells() : numPoints;
  if (cellData)
  {
    used.assign(static_cast<size_t>(numValues), 0);
    for (uint32_t c : tetCells)
    {
      used[c] = 1;
    }
  }
  else
  {
    used = this->Faces->GetPointUse(numPoints);
  }
  std::vector<double> values(static_cast<size_t>(numValues));
  double range[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest() };
  vtkIdType nonFinite = 0;
  for (vtkIdType i = 0; i < numValues; ++i)
  {
    values[i] = this->ScalarOf(scalars, i);
    if (!used[i])
    {
      continue;
    }
    if (std::isfinite(values[i]))
    {
      range[0] = std::min(range[0], values[i]);
      range[1] = std::max(range[1], values[i]);
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
  std::vector<float> normalized(static_cast<size_t>(numValues));
  for (vtkIdType i = 0; i < numValues; ++i)
  {
    double& s = values[i];
    s = std::isfinite(s) ? s : range[0];
    normalized[i] = span > 0.0 ? static_cast<float>((s - range[0]) / span) : 0.0f;
  }
  if (cellData)
  {
    this->CellScalars = true;
    this->TetrahedronScalars.resize(tetCells.size());
    this->Scalars.assign(static_cast<size_t>(numPoints), 0.0f);
    const std::vector<uint32_t>& tets = this->Faces->GetTetrahedra();
    for (size_t t = 0; t < tetCells.size(); ++t)
    {
      this->TetrahedronScalars[t] = normalized[tetCells[t]];
      for (int v = 0; v < 4; ++v)
      {
        this->Scalars[tets[4 * t + v]] = this->TetrahedronScalars[t];
      }
    }
    // The cells' values as the passes draw them: each used cell's code
    // (vtkHAVSCellOptics), the index of its value among the distinct ones.
    std::vector<float> codes(static_cast<size_t>(numValues), 0.0f);
    this->BuildCellValueCodes(values, used, codes);
    this->TetrahedronCodes.resize(tetCells.size());
    for (size_t t = 0; t < tetCells.size(); ++t)
    {
      this->TetrahedronCodes[t] = codes[tetCells[t]];
    }
    this->BuildCellScalarVertices(codes);
  }
  else
  {
    this->Scalars = std::move(normalized);
  }
  this->ScalarTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSMesh::Build(vtkDataObject* input, const ScalarSelection& selection,
  const std::function<void(double)>& progress)
{
  const double start = vtkTimerLog::GetUniversalTime();
  // What a new time step on the same mesh may keep (see below).
  const bool wasValid = this->Valid;
  const bool hadCellScalars = this->CellScalars;
  const ScalarSelection previousSelection = this->BuiltSelection;
  this->BuiltInput = input;
  this->BuiltInputTime = input ? input->GetMTime() : 0;
  this->BuiltSelection = selection;
  this->Valid = false;
  this->Error.clear();
  this->Warnings.clear();
  this->LastUpdate = UpdateNone;
  this->VectorMode = selection.VectorMode;
  this->VectorComponent = selection.VectorComponent;
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
  vtkDataSet* data = vtkDataSet::SafeDownCast(input);
  vtkSmartPointer<vtkUnstructuredGrid> appended;
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(input))
  {
    // Every block with the scalars, as one grid: one face order across them.
    vtkIdType skipped = 0, used = 0;
    appended = vtkHAVSTetrahedralizer::AppendBlocks(
      blocks,
      [&](vtkDataSet* leaf)
      {
        int flag = -1;
        return vtkAbstractMapper::GetScalars(leaf, selection.Mode, selection.AccessMode,
                 selection.Id, selection.Name.empty() ? nullptr : selection.Name.c_str(),
                 flag) != nullptr;
      },
      &skipped, &used);
    if (!appended)
    {
      return this->Fail("No block of the composite input has cells and the scalars to render.");
    }
    if (skipped > 0)
    {
      std::ostringstream w;
      w << skipped << " of the input's " << skipped + used
        << " blocks were skipped (no cells, or not the scalars to render).";
      this->Warnings.push_back(w.str());
    }
    data = appended;
  }
  if (!data)
  {
    return this->Fail(std::string("The input is a ") + input->GetClassName() +
      "; the vtkHAVS mappers need a vtkDataSet (an unstructured grid, or a structured, "
      "rectilinear or image grid).");
  }
  if (data->GetNumberOfPoints() == 0 || data->GetNumberOfCells() == 0)
  {
    std::ostringstream why;
    why << "The input grid is empty (" << data->GetNumberOfPoints() << " points, "
        << data->GetNumberOfCells() << " cells).";
    return this->Fail(why.str());
  }

  int cellFlag = -1;
  vtkDataArray* scalars = vtkAbstractMapper::GetScalars(data, selection.Mode, selection.AccessMode,
    selection.Id, selection.Name.empty() ? nullptr : selection.Name.c_str(), cellFlag);
  if (!scalars)
  {
    std::ostringstream why;
    why << "The input has no scalars to render (scalar mode " << ScalarModeName(selection.Mode)
        << (selection.Name.empty() ? "" : ", array " + selection.Name) << ").";
    return this->Fail(why.str());
  }
  if (cellFlag == 2)
  {
    return this->Fail("Field-data scalars cannot be rendered: use point or cell data.");
  }
  const bool cellData = cellFlag == 1;
  const std::string arrayName = scalars->GetName() ? scalars->GetName() : "";

  // A new time step on the same mesh (the same points and cells, as a
  // reader gives them for each step: compared by a hash of their contents)
  // keeps the faces, orders and GPU geometry; only the scalars are mapped
  // again. On a tessellated mesh (split or refined cells) through the
  // tessellation's source map: a tetrahedron's cell value is its cell's, a
  // point added by the refinement interpolates the cell's nodes as it did.
  // Not when point and cell scalars trade places.
  // The same points, cells and scalar array as last time in another data
  // object around them (a shallow copy: ParaView hands each of its
  // representation's mappers its own): nothing to map again.
  if (wasValid && this->HashedSource && cellData == hadCellScalars &&
    selection == previousSelection && scalars == this->MappedArray.GetPointer() &&
    scalars->GetMTime() == this->MappedArrayTime && GeometryHashOf(data) == this->GeometryHash)
  {
    this->HashedSource = data;
    this->LastUpdateSeconds = vtkTimerLog::GetUniversalTime() - start;
    report(1.0);
    this->Valid = true;
    return true; // LastUpdate stays UpdateNone
  }
  this->MappedArray = scalars;
  this->MappedArrayTime = scalars->GetMTime();

  vtkSmartPointer<vtkDataArray> stepScalars;
  if (wasValid && this->HashedSource && cellData == hadCellScalars &&
    selection.VectorMode == previousSelection.VectorMode &&
    selection.HigherOrderSubdivision == previousSelection.HigherOrderSubdivision &&
    GeometryHashOf(data) == this->GeometryHash)
  {
    if (!this->Tessellation.Tessellated)
    {
      stepScalars = scalars; // the grid is the input
    }
    else if (this->Sources.Valid && this->Sources.InputPoints == data->GetNumberOfPoints())
    {
      if (cellData)
      {
        stepScalars = this->Sources.MapCellArray(scalars);
      }
      else if (this->Sources.StencilOffsets.size() <= 1)
      {
        stepScalars = scalars; // (split cells keep the input's point ids)
      }
      else
      {
        stepScalars = this->Sources.MapPointArray(scalars);
      }
    }
  }
  if (stepScalars)
  {
    if (!this->Tessellation.Tessellated)
    {
      this->Grid = vtkUnstructuredGrid::SafeDownCast(data); // the same cells and points
    }
    if (!this->MapScalars(stepScalars, cellData, arrayName))
    {
      return false;
    }
    this->HashedSource = data;
    this->LastUpdate = UpdateScalars;
    this->LastUpdateSeconds = vtkTimerLog::GetUniversalTime() - start;
    report(1.0);
    this->Valid = true;
    return true;
  }

  // A new mesh: everything again.
  this->BuildTime.Modified();
  this->Grid = nullptr;
  this->HashedSource = nullptr;
  this->CellScalars = false;
  this->TetrahedronScalars.clear();
  this->TetrahedronCodes.clear();
  this->CellValues.clear();
  this->FaceVertexPoints.clear();
  this->FaceVertexScalars.clear();
  this->FaceVertexIds.clear();

  // The cells as tetrahedra.
  report(0.0);
  this->Grid = vtkHAVSTetrahedralizer::Tetrahedralize(data, &this->Tessellation,
    selection.HigherOrderSubdivision, vtkHAVSTetrahedralizer::SplitOrdered, &this->Sources);
  if (!this->Grid || this->Grid->GetNumberOfCells() == 0)
  {
    std::ostringstream why;
    why << "No 3D cells to render in the input (" << this->Tessellation.LowerDimensionCells
        << " of its " << this->Tessellation.InputCells << " cells are vertices, lines or polygons; "
        << this->Tessellation.InvalidCells << " refer to points that do not exist).";
    return this->Fail(why.str());
  }
  if (this->Tessellation.InvalidCells > 0)
  {
    this->Warnings.push_back(InvalidCellsWarning(this->Tessellation.InvalidCells));
  }
  if (this->Tessellation.UnrefinedNonLinearCells > 0)
  {
    std::ostringstream w;
    w << this->Tessellation.UnrefinedNonLinearCells
      << " non-linear cells of types the higher-order subdivision does not know are not "
         "refined: they are split at their nodes by VTK.";
    this->Warnings.push_back(w.str());
  }
  if (this->Tessellation.CornerPyramids > 0)
  {
    std::ostringstream w;
    w << this->Tessellation.CornerPyramids
      << " Lagrange or Bezier pyramids are drawn as the linear pyramids of their five corners "
         "(this VTK has no cell class to interpolate them).";
    this->Warnings.push_back(w.str());
  }
  if (this->Tessellation.LowerDimensionCells > 0)
  {
    std::ostringstream w;
    w << this->Tessellation.LowerDimensionCells
      << " cells that are not 3D (vertices, lines, polygons) were skipped.";
    this->Warnings.push_back(w.str());
  }
  if (this->Tessellation.Tessellated)
  {
    // The split grid carries the arrays under the same names and positions.
    scalars = cellData ? this->Grid->GetCellData()->GetArray(arrayName.c_str())
                       : this->Grid->GetPointData()->GetArray(arrayName.c_str());
    if (!scalars)
    {
      int flag = -1;
      scalars = vtkAbstractMapper::GetScalars(this->Grid, selection.Mode, selection.AccessMode,
        selection.Id, selection.Name.empty() ? nullptr : selection.Name.c_str(), flag);
      if (!scalars || flag != cellFlag)
      {
        return this->Fail("The scalars were lost splitting the cells into tetrahedra.");
      }
    }
  }
  report(0.2);
  if (!this->Faces->Build(this->Grid))
  {
    return this->Fail("No tetrahedra to render in the input.");
  }
  report(0.6);
  if (this->Faces->GetNumberOfSkippedCells() > 0)
  {
    std::ostringstream w;
    w << this->Faces->GetNumberOfSkippedCells() << " cells could not be split into tetrahedra "
      << "and were skipped.";
    this->Warnings.push_back(w.str());
  }
  if (this->Faces->GetNumberOfInvalidCells() > 0)
  {
    this->Warnings.push_back(InvalidCellsWarning(this->Faces->GetNumberOfInvalidCells()));
  }
  // Collapsed pieces (a point id repeated) are what degenerate cells give
  // wherever they are split; they say nothing about the mesh and are not
  // counted towards the warning.
  const vtkIdType degenerate =
    this->Faces->GetNumberOfDegenerateTetrahedra() - this->Faces->GetNumberOfCollapsedTetrahedra();
  if (degenerate >
    DegenerateWarningShare * static_cast<double>(degenerate + this->Faces->GetNumberOfTetrahedra()))
  {
    std::ostringstream w;
    w << degenerate << " of " << degenerate + this->Faces->GetNumberOfTetrahedra()
      << " tetrahedra are degenerate and were dropped (zero volume with distinct points, or "
      << this->Faces->GetNumberOfThinTetrahedra() << " thinner than "
      << this->Faces->GetMinimumRelativeThickness()
      << " of the mesh's extent across them): more than " << 100.0 * DegenerateWarningShare
      << " %, the mesh may be broken.";
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

  // Points, shifted by the bounds' centre so that floats keep their precision.
  vtkUnstructuredGrid* grid = this->Grid;
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

  if (!this->MapScalars(scalars, cellData, arrayName))
  {
    return false;
  }
  this->GeometryHash = GeometryHashOf(data);
  this->HashedSource = data;
  this->LastUpdate = UpdateFull;
  this->LastUpdateSeconds = vtkTimerLog::GetUniversalTime() - start;
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
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << " ("
     << this->ScalarDescription << ")\n";
  os << indent << "Tessellated: " << this->Tessellation.Tessellated << " ("
     << this->Tessellation.SplitCells << " cells split into " << this->Tessellation.OutputTetrahedra
     << " tetrahedra; higher-order subdivision " << this->Tessellation.HigherOrderSubdivision
     << ": " << this->Tessellation.RefinedCells << " cells refined, "
     << this->Tessellation.AddedPoints << " points added; "
     << this->Tessellation.LowerDimensionCells << " lower-dimensional cells left out)\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSMesh::GetMemoryBytes() const
{
  // The tetrahedralized grid when it is the mesh's own (not the input's).
  const size_t grid = this->Grid && this->Tessellation.Tessellated
    ? static_cast<size_t>(this->Grid->GetActualMemorySize()) * 1024
    : 0;
  return grid + this->Faces->GetMemoryBytes() +
    vtkHAVSMemory::Bytes(this->Points, this->Scalars, this->TetrahedronScalars,
      this->TetrahedronCodes, this->CellValues, this->FaceVertexPoints, this->FaceVertexScalars,
      this->FaceVertexIds, this->Sources.StencilOffsets, this->Sources.StencilIds,
      this->Sources.StencilWeights, this->Sources.Cells);
}

//------------------------------------------------------------------------------
size_t vtkHAVSMesh::MakeTaggedVertices(const std::vector<float>& points,
  const std::vector<float>& scalars, int components, const std::vector<uint32_t>& triangles,
  const std::vector<uint8_t>& boundary, std::vector<float>& taggedPoints,
  std::vector<float>& taggedScalars, std::vector<uint32_t>& indices,
  const std::vector<float>* vectors, std::vector<float>* taggedVectors)
{
  const size_t faces = triangles.size() / 3;
  const size_t nc = static_cast<size_t>(components);
  size_t boundaryFaces = 0;
  for (size_t f = 0; f < faces && f < boundary.size(); ++f)
  {
    boundaryFaces += boundary[f] ? 1 : 0;
  }
  taggedPoints.assign(9 * boundaryFaces, 0.0f);
  taggedScalars.assign(3 * nc * boundaryFaces, 0.0f);
  const bool copyVectors = vectors && taggedVectors && vectors->size() == points.size();
  if (taggedVectors)
  {
    taggedVectors->assign(copyVectors ? 9 * boundaryFaces : 0, 0.0f);
  }
  if (boundaryFaces == 0)
  {
    indices.clear(); // nothing rewritten: the triangles are drawn as they are
    return 0;
  }
  indices = triangles;
  uint32_t next = static_cast<uint32_t>(points.size() / 3);
  size_t b = 0;
  for (size_t f = 0; f < faces && f < boundary.size(); ++f)
  {
    if (!boundary[f])
    {
      continue;
    }
    // A face wound the other way than its vertices' cell-scalar pairs
    // (flag 2: out of a visible cell next to an invisible one) swaps them.
    const bool swapPair = boundary[f] == 2 && nc == 2;
    for (int v = 0; v < 3; ++v, ++b)
    {
      const uint32_t p = triangles[3 * f + v];
      std::copy_n(&points[3 * size_t(p)], 3, &taggedPoints[3 * b]);
      if (copyVectors)
      {
        std::copy_n(&(*vectors)[3 * size_t(p)], 3, &(*taggedVectors)[3 * b]);
      }
      for (size_t c = 0; c < nc; ++c)
      {
        taggedScalars[nc * b + c] = scalars[nc * p + (swapPair ? 1 - c : c)] + 2.0f;
      }
      indices[3 * f + v] = next++;
    }
  }
  return boundaryFaces;
}

VTK_ABI_NAMESPACE_END
