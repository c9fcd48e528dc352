/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTetrahedralizer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTetrahedralizer.h"

#include "vtkAppendFilter.h"
#include "vtkBezierHexahedron.h"
#include "vtkBezierTetra.h"
#include "vtkBezierWedge.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkGenericCell.h"
#include "vtkHAVSVTKCompat.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkHigherOrderWedge.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPyramid.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
const char* const kOriginalCell = "vtkHAVSTetrahedralizerOriginalCell";
const char* const kSourceCell = "vtkHAVSTetrahedralizerSourceCell";

/**
 * VTK's split of every cell but the quadratic tetrahedra, which get the
 * canonical eight tetrahedra, and the Lagrange and Bezier tetrahedra, split
 * on their nodes' lattice. nullptr when VTK's split renumbered the points
 * (then its split is used for all).
 */
vtkSmartPointer<vtkUnstructuredGrid> SplitWithCanonicalQuadraticTetrahedra(
  vtkDataSet* data, bool higherOrderLattice)
{
  auto* input = vtkUnstructuredGrid::SafeDownCast(data);
  if (!input)
  {
    return nullptr;
  }
  // VTK's split, each tetrahedron knowing the cell it came from.
  vtkNew<vtkUnstructuredGrid> tagged;
  tagged->ShallowCopy(input);
  vtkNew<vtkIdTypeArray> original;
  original->SetName(kOriginalCell);
  original->SetNumberOfTuples(input->GetNumberOfCells());
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    original->SetValue(c, c);
  }
  tagged->GetCellData()->AddArray(original);
  vtkNew<vtkDataSetTriangleFilter> split;
  split->SetInputData(tagged);
  split->TetrahedraOnlyOn();
  split->Update();
  vtkUnstructuredGrid* vtkSplit = split->GetOutput();
  auto* from = vtkIdTypeArray::SafeDownCast(vtkSplit->GetCellData()->GetArray(kOriginalCell));
  if (!from || vtkSplit->GetNumberOfPoints() != input->GetNumberOfPoints())
  {
    return nullptr;
  }

  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(input->GetPoints());
  out->GetPointData()->PassData(input->GetPointData());
  vtkCellData* outCD = out->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), vtkSplit->GetNumberOfCells());
  out->Allocate(vtkSplit->GetNumberOfCells());
  auto insert = [&](const vtkIdType ids[4], vtkIdType source)
  {
    const vtkIdType cell = out->InsertNextCell(VTK_TETRA, 4, ids);
    outCD->CopyData(input->GetCellData(), source, cell);
  };
  auto lattice = [higherOrderLattice](int type)
  {
    return type == VTK_QUADRATIC_TETRA ||
      (higherOrderLattice && (type == VTK_LAGRANGE_TETRAHEDRON || type == VTK_BEZIER_TETRAHEDRON));
  };
  for (vtkIdType t = 0; t < vtkSplit->GetNumberOfCells(); ++t)
  {
    const vtkIdType source = from->GetValue(t);
    if (lattice(input->GetCellType(source)))
    {
      continue;
    }
    vtkIdType npts = 0;
    const vtkIdType* ids = nullptr;
    vtkSplit->GetCellPoints(t, npts, ids);
    insert(ids, source);
  }
  // Lagrange and Bezier tetrahedra of order p: their nodes are the lattice
  // of p segments per edge; it is split by Freudenthal's triangulation of
  // the cubes of x1 = i + j + k, x2 = j + k, x3 = k (the simplex p >= x1 >=
  // x2 >= x3 >= 0), whose faces are the regular lattice triangulation, the
  // same from both sides (and the canonical eight's for p = 2).
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> nodeAt;
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    const int type = input->GetCellType(c);
    if (!higherOrderLattice || (type != VTK_LAGRANGE_TETRAHEDRON && type != VTK_BEZIER_TETRAHEDRON))
    {
      continue;
    }
    input->GetCell(c, cell);
    const int nodes = static_cast<int>(cell->GetNumberOfPoints());
    int p = 1;
    while ((p + 1) * (p + 2) * (p + 3) / 6 < nodes)
    {
      ++p;
    }
    if ((p + 1) * (p + 2) * (p + 3) / 6 != nodes)
    {
      continue; // (not a complete tetrahedral lattice: left out)
    }
    const double* pc = cell->GetParametricCoords();
    const int side = p + 1;
    auto index = [&](int i, int j, int k) { return i + side * (j + side * k); };
    nodeAt.assign(static_cast<size_t>(side) * side * side, -1);
    for (int v = 0; v < nodes; ++v)
    {
      const int i = static_cast<int>(std::lround(pc[3 * v] * p));
      const int j = static_cast<int>(std::lround(pc[3 * v + 1] * p));
      const int k = static_cast<int>(std::lround(pc[3 * v + 2] * p));
      if (i >= 0 && j >= 0 && k >= 0 && i + j + k <= p)
      {
        nodeAt[index(i, j, k)] = cell->GetPointId(v);
      }
    }
    // A lattice point (x1, x2, x3) of the simplex.
    auto at = [&](int x1, int x2, int x3) -> vtkIdType
    {
      if (!(p >= x1 && x1 >= x2 && x2 >= x3 && x3 >= 0))
      {
        return -1;
      }
      return nodeAt[index(x1 - x2, x2 - x3, x3)];
    };
    static const int orders[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
      { 2, 0, 1 }, { 2, 1, 0 } };
    for (int a = 0; a < p; ++a)
    {
      for (int b = 0; b <= a; ++b)
      {
        for (int d = 0; d <= b; ++d)
        {
          for (const auto& o : orders)
          {
            int x[3] = { a, b, d };
            vtkIdType ids[4];
            ids[0] = at(x[0], x[1], x[2]);
            for (int step = 0; step < 3; ++step)
            {
              ++x[o[step]];
              ids[step + 1] = at(x[0], x[1], x[2]);
            }
            if (ids[0] >= 0 && ids[1] >= 0 && ids[2] >= 0 && ids[3] >= 0)
            {
              insert(ids, c);
            }
          }
        }
      }
    }
  }
  // vtkQuadraticTetra's nodes: corners 0-3, then the edges 01, 12, 20, 03, 13, 23.
  for (vtkIdType c = 0; c < input->GetNumberOfCells(); ++c)
  {
    if (input->GetCellType(c) != VTK_QUADRATIC_TETRA)
    {
      continue;
    }
    vtkIdType npts = 0;
    const vtkIdType* n = nullptr;
    input->GetCellPoints(c, npts, n);
    const vtkIdType e01 = n[4], e12 = n[5], e20 = n[6], e03 = n[7], e13 = n[8], e23 = n[9];
    const vtkIdType tets[8][4] = { { n[0], e01, e20, e03 }, { n[1], e12, e01, e13 },
      { n[2], e20, e12, e23 }, { n[3], e03, e13, e23 },
      // the octahedron e01 e12 e20 e03 e13 e23 around its diagonal e01-e23
      { e01, e23, e12, e13 }, { e01, e23, e13, e03 }, { e01, e23, e03, e20 },
      { e01, e23, e20, e12 } };
    for (const auto& t : tets)
    {
      insert(t, c);
    }
  }
  return out;
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSTetrahedralizer::AppendBlocks(
  vtkCompositeDataSet* blocks, const std::function<bool(vtkDataSet*)>& keep, vtkIdType* skipped,
  vtkIdType* appended)
{
  vtkIdType left = 0, used = 0;
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOff();
  vtkDataSet* first = nullptr;
  if (blocks)
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(blocks->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
      if (!leaf || leaf->GetNumberOfCells() == 0 || (keep && !keep(leaf)))
      {
        ++left;
        continue;
      }
      first = first ? first : leaf;
      append->AddInputData(leaf);
      ++used;
    }
  }
  if (skipped)
  {
    *skipped = left;
  }
  if (appended)
  {
    *appended = used;
  }
  if (used == 0)
  {
    return nullptr;
  }
  append->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = append->GetOutput();
  vtkDataArray* pointScalars = first->GetPointData()->GetScalars();
  if (pointScalars && pointScalars->GetName())
  {
    grid->GetPointData()->SetActiveScalars(pointScalars->GetName());
  }
  vtkDataArray* cellScalars = first->GetCellData()->GetScalars();
  if (cellScalars && cellScalars->GetName())
  {
    grid->GetCellData()->SetActiveScalars(cellScalars->GetName());
  }
  return grid;
}

namespace
{
/// Lagrange and Bezier pyramids: VTK 9.2 has no cell class for them (its
/// vtkGenericCell makes them empty cells), so their shape functions are not
/// available; they are taken as the linear pyramid of their corners (the
/// first five nodes, as VTK orders every higher-order cell's).
bool IsCornerPyramid(int type)
{
  return type == VTK_LAGRANGE_PYRAMID || type == VTK_BEZIER_PYRAMID;
}

/// A cell type's dimension (vtkCellTypes::GetDimension asks a vtkGenericCell,
/// which says 0, and logs an error, for the pyramids above).
int CellDimension(int type)
{
  return IsCornerPyramid(type) ? 3 : havs_vtk::CellTypeDimension(type);
}

/// An unstructured grid's cells whose point ids are all in range (and
/// Lagrange and Bezier pyramids with their five corners at least); nullptr
/// when every cell is (then the input is used as it is). VTK's split reads a
/// cell's points by id: a corrupt file's id must never reach it.
vtkSmartPointer<vtkUnstructuredGrid> WithoutInvalidCells(vtkDataSet* data, vtkIdType& invalid)
{
  invalid = 0;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || !grid->GetCells())
  {
    return nullptr;
  }
  const vtkIdType numberOfPoints = grid->GetNumberOfPoints();
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  std::vector<char> valid(static_cast<size_t>(numberOfCells), 1);
  vtkCellArray* cells = grid->GetCells();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    cells->GetCellAtId(c, ids);
    if (IsCornerPyramid(grid->GetCellType(c)) && ids->GetNumberOfIds() < 5)
    {
      valid[c] = 0;
      ++invalid;
      continue;
    }
    for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
    {
      const vtkIdType id = ids->GetId(i);
      if (id < 0 || id >= numberOfPoints)
      {
        valid[c] = 0;
        ++invalid;
        break;
      }
    }
  }
  if (invalid == 0)
  {
    return nullptr;
  }
  auto kept = vtkSmartPointer<vtkUnstructuredGrid>::New();
  kept->SetPoints(grid->GetPoints());
  kept->GetPointData()->ShallowCopy(grid->GetPointData());
  kept->GetCellData()->CopyAllocate(grid->GetCellData(), numberOfCells - invalid);
  kept->Allocate(numberOfCells - invalid);
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    if (valid[c])
    {
      cells->GetCellAtId(c, ids);
      const vtkIdType id = kept->InsertNextCell(grid->GetCellType(c), ids);
      kept->GetCellData()->CopyData(grid->GetCellData(), c, id);
    }
  }
  return kept;
}

/**
 * Level 0's pyramids on their nodes: the 19-node (triquadratic) pyramids of
 * `data` replaced by the linear pieces of their nodes' lattice of two
 * segments per edge (level 1's lattice of the subdivision, which uses 14 of
 * the 19 nodes: the corners, the edges' middles, the base's middle), and the
 * Lagrange and Bezier pyramids by the linear pyramid of their corners; the
 * other cells, the points and the point and cell data as they are; nullptr
 * when there is no such pyramid (`corners`: the Lagrange and Bezier ones). VTK's split of the 19
 * nodes cuts each triangular face around its middle node, and the base by local point order:
 * neighbours (a quadratic tetrahedron's four sub-triangles, another pyramid's
 * base) need not agree, and they crack (measured: 576 of 832 boundary
 * triangles inside a shell). Here a triangular face is cut into the four
 * sub-triangles of its edges' middles (as the canonical quadratic
 * tetrahedron's) and the base into four quadrilaterals that the ordered
 * triangulator splits by global point ids, the same from both sides. The
 * pieces, as in RefinePyramid at n = 2: an upright pyramid on each base
 * quarter and on the middle layer, one inverted under the middle layer, four
 * tetrahedra across the base's inner edges.
 */
vtkSmartPointer<vtkUnstructuredGrid> WithPyramidsOnTheirNodes(vtkDataSet* data, vtkIdType& corners)
{
  corners = 0;
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid)
  {
    return nullptr;
  }
  const vtkIdType numberOfCells = grid->GetNumberOfCells();
  vtkIdType triquadratic = 0;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    triquadratic += grid->GetCellType(c) == VTK_TRIQUADRATIC_PYRAMID ? 1 : 0;
    corners += IsCornerPyramid(grid->GetCellType(c)) ? 1 : 0;
  }
  if (triquadratic + corners == 0)
  {
    return nullptr;
  }
  static const int kPieces[10][5] = { { 0, 5, 13, 8, 9 }, { 5, 1, 6, 13, 10 }, { 8, 13, 7, 3, 12 },
    { 13, 6, 2, 7, 11 }, { 9, 10, 11, 12, 4 }, { 9, 12, 11, 10, 13 }, { 5, 13, 9, 10, -1 },
    { 8, 13, 9, 12, -1 }, { 13, 6, 10, 11, -1 }, { 13, 7, 12, 11, -1 } };
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->SetPoints(grid->GetPoints());
  out->GetPointData()->PassData(grid->GetPointData());
  vtkCellData* outCD = out->GetCellData();
  const vtkIdType outCells = numberOfCells + 9 * triquadratic;
  outCD->CopyAllocate(grid->GetCellData(), outCells);
  out->Allocate(outCells);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    grid->GetCellPoints(c, ids);
    const int type = grid->GetCellType(c);
    if (IsCornerPyramid(type))
    {
      ids->SetNumberOfIds(5); // (five at least: WithoutInvalidCells)
      outCD->CopyData(grid->GetCellData(), c, out->InsertNextCell(VTK_PYRAMID, ids));
      continue;
    }
    if (type != VTK_TRIQUADRATIC_PYRAMID || ids->GetNumberOfIds() < 14)
    {
      outCD->CopyData(grid->GetCellData(), c, out->InsertNextCell(type, ids));
      continue;
    }
    for (const auto& piece : kPieces)
    {
      const int n = piece[4] < 0 ? 4 : 5;
      vtkIdType pts[5];
      for (int i = 0; i < n; ++i)
      {
        pts[i] = ids->GetId(piece[i]);
      }
      const vtkIdType id = out->InsertNextCell(n == 4 ? VTK_TETRA : VTK_PYRAMID, n, pts);
      outCD->CopyData(grid->GetCellData(), c, id);
    }
  }
  return out;
}
}

namespace
{
/// The parametric families a non-linear cell is refined in.
enum Family
{
  NotRefined,
  HexahedronFamily,
  TetrahedronFamily,
  WedgeFamily,
  PyramidFamily
};

Family FamilyOf(int type)
{
  switch (type)
  {
    case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON:
    case VTK_BEZIER_HEXAHEDRON:
      return HexahedronFamily;
    case VTK_QUADRATIC_TETRA:
    case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_BEZIER_TETRAHEDRON:
      return TetrahedronFamily;
    case VTK_QUADRATIC_WEDGE:
    case VTK_QUADRATIC_LINEAR_WEDGE:
    case VTK_BIQUADRATIC_QUADRATIC_WEDGE:
    case VTK_LAGRANGE_WEDGE:
    case VTK_BEZIER_WEDGE:
      return WedgeFamily;
    case VTK_QUADRATIC_PYRAMID:
    case VTK_TRIQUADRATIC_PYRAMID:
    case VTK_LAGRANGE_PYRAMID: // (as the linear pyramid of their corners: see CornerPyramid)
    case VTK_BEZIER_PYRAMID:
      return PyramidFamily;
    default:
      return NotRefined;
  }
}

int CornersOf(Family f)
{
  return f == HexahedronFamily ? 8 : f == TetrahedronFamily ? 4 : f == PyramidFamily ? 5 : 6;
}

/// A lattice point's identity: the parent's corner ids (sorted) with their
/// integer weights (summing to N^3). The same from every cell sharing the point.
using PointKey = std::vector<std::pair<vtkIdType, long long>>;

/// One refined cell: its lattice points (key, position, interpolation
/// weights over the cell's nodes) and its linear pieces (local lattice indices).
struct RefinedCell
{
  Family Kind = NotRefined;
  std::vector<int> Lattice; ///< dense (N+1)^3 index -> local point (-1: none)
  std::vector<PointKey> Keys;
  std::vector<double> Positions;        ///< 3 per local point
  std::vector<double> Weights;          ///< nodes per local point
  std::vector<vtkIdType> NodeIds;       ///< the cell's point ids
  std::vector<std::vector<int>> Pieces; ///< local points of each linear piece
  std::vector<int> PieceTypes;

  /// A new local point at lattice index `index`: the cell evaluated at
  /// `pcoords` (position and weights), `key` sorted and stored.
  void AddPoint(
    vtkCell* cell, int index, PointKey key, double pcoords[3], std::vector<double>& weights)
  {
    std::sort(key.begin(), key.end());
    int subId = 0;
    double x[3];
    cell->EvaluateLocation(subId, pcoords, x, weights.data());
    this->Lattice[index] = static_cast<int>(this->Keys.size());
    this->Keys.push_back(std::move(key));
    this->Positions.insert(this->Positions.end(), x, x + 3);
    this->Weights.insert(this->Weights.end(), weights.begin(), weights.end());
  }
};

/// The recursive canonical split of a lattice tetrahedron (corners as
/// lattice coordinates) into 8^depth tetrahedra.
void SplitLatticeTetrahedron(const std::array<std::array<int, 3>, 4>& t, int depth,
  std::vector<std::array<std::array<int, 3>, 4>>& out)
{
  if (depth == 0)
  {
    out.push_back(t);
    return;
  }
  auto mid = [&](int a, int b)
  {
    return std::array<int, 3>{ (t[a][0] + t[b][0]) / 2, (t[a][1] + t[b][1]) / 2,
      (t[a][2] + t[b][2]) / 2 };
  };
  const auto e01 = mid(0, 1), e12 = mid(1, 2), e20 = mid(2, 0), e03 = mid(0, 3), e13 = mid(1, 3),
             e23 = mid(2, 3);
  const std::array<std::array<std::array<int, 3>, 4>, 8> children = { { { t[0], e01, e20, e03 },
    { t[1], e12, e01, e13 }, { t[2], e20, e12, e23 }, { t[3], e03, e13, e23 },
    { e01, e23, e12, e13 }, { e01, e23, e13, e03 }, { e01, e23, e03, e20 },
    { e01, e23, e20, e12 } } };
  for (const auto& c : children)
  {
    SplitLatticeTetrahedron(c, depth - 1, out);
  }
}

/// Cell `c` of `input` into `cell`, a Lagrange or Bezier cell with its
/// order (the grid's HigherOrderDegrees, or uniform from its point count) and
/// a Bezier cell with its rational weights (when the points have them).
void GetCell(vtkUnstructuredGrid* input, vtkIdType c, vtkGenericCell* cell)
{
  input->GetCell(c, cell);
  vtkCell* actual = cell->GetRepresentativeCell();
  const vtkIdType npts = cell->GetNumberOfPoints();
  vtkCellData* cd = input->GetCellData();
  const bool degrees = cd->GetHigherOrderDegrees() != nullptr;
  if (auto* hex = vtkHigherOrderHexahedron::SafeDownCast(actual))
  {
    degrees ? hex->SetOrderFromCellData(cd, npts, c) : hex->SetUniformOrderFromNumPoints(npts);
  }
  else if (auto* wedge = vtkHigherOrderWedge::SafeDownCast(actual))
  {
    degrees ? wedge->SetOrderFromCellData(cd, npts, c) : wedge->SetUniformOrderFromNumPoints(npts);
  }
  if (input->GetPointData()->GetRationalWeights())
  {
    if (auto* bh = vtkBezierHexahedron::SafeDownCast(actual))
    {
      bh->SetRationalWeightsFromPointData(input->GetPointData(), npts);
    }
    else if (auto* bt = vtkBezierTetra::SafeDownCast(actual))
    {
      bt->SetRationalWeightsFromPointData(input->GetPointData(), npts);
    }
    else if (auto* bw = vtkBezierWedge::SafeDownCast(actual))
    {
      bw->SetRationalWeightsFromPointData(input->GetPointData(), npts);
    }
  }
}

/// Cell `c` of `input` (a Lagrange or Bezier pyramid) as the linear pyramid
/// of its corners, into `pyramid`.
void CornerPyramid(vtkUnstructuredGrid* input, vtkIdType c, vtkPyramid* pyramid)
{
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkNew<vtkIdList> scratch;
  input->GetCellPoints(c, npts, ids, scratch);
  for (int i = 0; i < 5; ++i)
  {
    const vtkIdType id = ids[i]; // (five at least: WithoutInvalidCells)
    double x[3];
    input->GetPoint(id, x);
    pyramid->GetPointIds()->SetId(i, id);
    pyramid->GetPoints()->SetPoint(i, x);
  }
}

/**
 * Refines a non-linear pyramid (any thread). The lattice: layer k = 0 … N
 * (the apex's integer weight k, scale N) holds the (m + 1)^2 points (i, j),
 * m = N - k, 0 <= i, j <= m, whose corner weights are those of the linear
 * pyramid at the parametric point (i / m, j / m, k / N): the base corners
 * (m - i)(m - j) / (m N) … and the apex k / N. On the base they are the
 * bilinear weights of a hexahedron's refined face, on a triangular face the
 * barycentric ones of a tetrahedron's (or a wedge's): the keys, and so the
 * points, are the same from both sides. The pieces between layers k and k + 1
 * (the tetrahedral-octahedral lattice): an upright pyramid on every base
 * square, an inverted one under every square of the layer above, and a
 * tetrahedron across every inner edge of the layer below; their quadrilaterals
 * are split later by the ordered triangulator (the same diagonal from both
 * sides), their triangular faces on the cell's faces are the face's unique
 * lattice triangulation.
 */
void RefinePyramid(vtkCell* cell, int level, int split, RefinedCell& r)
{
  const int n = 1 << level;
  const int side = n + 1;
  const int nodes = static_cast<int>(cell->GetNumberOfPoints());
  const double* nodePcoords = cell->GetParametricCoords();
  r.Kind = PyramidFamily;
  r.NodeIds.assign(nodes, 0);
  for (int i = 0; i < nodes; ++i)
  {
    r.NodeIds[i] = cell->GetPointId(i);
  }
  // vtkQuadraticPyramid's parametric space is the collapsed hexahedron (apex
  // at (0, 0, 1)); VTK 9.2's vtkTriQuadraticPyramid's a pyramid (apex at
  // (0.5, 0.5, 1)), where a point is the corners' parametric coordinates
  // weighted as the linear pyramid's.
  const bool collapsed = nodePcoords[12] < 0.25 && nodePcoords[13] < 0.25;
  const long long nn = static_cast<long long>(n) * n;
  auto index = [&](int i, int j, int k) { return i + side * (j + side * k); };
  r.Lattice.assign(static_cast<size_t>(side) * side * side, -1);
  std::vector<double> weights(nodes);
  for (int k = 0; k <= n; ++k)
  {
    const int m = n - k;
    for (int j = 0; j <= m; ++j)
    {
      for (int i = 0; i <= m; ++i)
      {
        PointKey key;
        double pcoords[3] = { 0.0, 0.0, 1.0 };
        if (m == 0)
        {
          key.emplace_back(r.NodeIds[4], nn * n);
          std::copy_n(nodePcoords + 12, 3, pcoords);
        }
        else
        {
          // The corners' weights times m N^3 (they sum to m N^3).
          const long long num[5] = { (m - i) * static_cast<long long>(m - j) * nn,
            i * static_cast<long long>(m - j) * nn, i * static_cast<long long>(j) * nn,
            (m - i) * static_cast<long long>(j) * nn, static_cast<long long>(k) * m * nn };
          bool divisible = true;
          for (long long v : num)
          {
            divisible = divisible && v % m == 0;
          }
          // On the cell's faces the weights are integers at scale N^3, as
          // every family's; inside, where they need not be, the key keeps
          // the scale m N^3 and says so (a point inside is this cell's own).
          for (int c = 0; c < 5; ++c)
          {
            if (num[c] != 0)
            {
              key.emplace_back(r.NodeIds[c], divisible ? num[c] / m : num[c]);
            }
          }
          if (!divisible)
          {
            key.emplace_back(-1, m);
          }
          if (collapsed)
          {
            pcoords[0] = static_cast<double>(i) / m;
            pcoords[1] = static_cast<double>(j) / m;
            pcoords[2] = static_cast<double>(k) / n;
          }
          else
          {
            pcoords[2] = 0.0;
            for (int c = 0; c < 5; ++c)
            {
              for (int a = 0; a < 3; ++a)
              {
                pcoords[a] += static_cast<double>(num[c]) / static_cast<double>(m * nn * n) *
                  nodePcoords[3 * c + a];
              }
            }
          }
        }
        r.AddPoint(cell, index(i, j, k), std::move(key), pcoords, weights);
      }
    }
  }
  auto at = [&](int i, int j, int k) { return r.Lattice[index(i, j, k)]; };
  auto addPyramid = [&](std::vector<int> ids)
  {
    if (split == vtkHAVSTetrahedralizer::SplitLocalOrder)
    {
      // The control: the base split along its local diagonal 0-2.
      r.Pieces.push_back({ ids[0], ids[1], ids[2], ids[4] });
      r.Pieces.push_back({ ids[0], ids[2], ids[3], ids[4] });
      r.PieceTypes.push_back(VTK_TETRA);
      r.PieceTypes.push_back(VTK_TETRA);
      return;
    }
    r.Pieces.push_back(std::move(ids));
    r.PieceTypes.push_back(VTK_PYRAMID);
  };
  auto addTetrahedron = [&](std::vector<int> ids)
  {
    r.Pieces.push_back(std::move(ids));
    r.PieceTypes.push_back(VTK_TETRA);
  };
  for (int k = 0; k < n; ++k)
  {
    const int m = n - k;
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        // Upright: the square (i, j) of layer k, apex the point above its centre.
        addPyramid(
          { at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k), at(i, j, k + 1) });
        if (i + 1 < m && j + 1 < m)
        {
          // Inverted: the square (i, j) of layer k + 1, apex the point below its centre.
          addPyramid({ at(i, j, k + 1), at(i, j + 1, k + 1), at(i + 1, j + 1, k + 1),
            at(i + 1, j, k + 1), at(i + 1, j + 1, k) });
        }
        if (i + 1 < m)
        {
          // Across the inner edge x = i + 1 of the square.
          addTetrahedron(
            { at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j, k + 1), at(i + 1, j, k + 1) });
        }
        if (j + 1 < m)
        {
          // Across the inner edge y = j + 1.
          addTetrahedron(
            { at(i, j + 1, k), at(i + 1, j + 1, k), at(i, j, k + 1), at(i, j + 1, k + 1) });
        }
      }
    }
  }
}

/// Refines one cell (any thread): fills `r` from `cell` at `level`.
void RefineCell(vtkCell* cell, Family family, int level, int split, RefinedCell& r)
{
  if (family == PyramidFamily)
  {
    RefinePyramid(cell, level, split, r);
    return;
  }
  const int n = 1 << level;
  const int side = n + 1;
  const int corners = CornersOf(family);
  const int nodes = static_cast<int>(cell->GetNumberOfPoints());
  const double* nodePcoords = cell->GetParametricCoords();
  r.Kind = family;
  r.NodeIds.assign(nodes, 0);
  for (int i = 0; i < nodes; ++i)
  {
    r.NodeIds[i] = cell->GetPointId(i);
  }
  // Each corner's position in the unit lattice cube / simplex (0 or 1 per axis).
  int cornerBits[8][3];
  for (int c = 0; c < corners; ++c)
  {
    for (int a = 0; a < 3; ++a)
    {
      cornerBits[c][a] = nodePcoords[3 * c + a] > 0.5 ? 1 : 0;
    }
  }
  const long long n3 = static_cast<long long>(n) * n * n;
  // The integer weight of corner c at lattice point (i, j, k), scale N^3.
  auto weight = [&](int c, int i, int j, int k) -> long long
  {
    const int* b = cornerBits[c];
    switch (family)
    {
      case HexahedronFamily:
        return static_cast<long long>(b[0] ? i : n - i) * (b[1] ? j : n - j) * (b[2] ? k : n - k);
      case TetrahedronFamily:
      {
        const int l = b[0] ? i : b[1] ? j : b[2] ? k : n - i - j - k;
        return static_cast<long long>(l) * n * n;
      }
      default: // wedge: triangle (i, j) times line k
      {
        const int l = b[0] ? i : b[1] ? j : n - i - j;
        return static_cast<long long>(l) * (b[2] ? k : n - k) * n;
      }
    }
  };
  auto inside = [&](int i, int j, int k)
  {
    switch (family)
    {
      case HexahedronFamily:
        return true;
      case TetrahedronFamily:
        return i + j + k <= n;
      default:
        return i + j <= n;
    }
  };
  auto index = [&](int i, int j, int k) { return i + side * (j + side * k); };
  r.Lattice.assign(static_cast<size_t>(side) * side * side, -1);
  std::vector<double> weights(nodes);
  for (int k = 0; k <= n; ++k)
  {
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        if (!inside(i, j, k))
        {
          continue;
        }
        PointKey key;
        double pcoords[3] = { 0.0, 0.0, 0.0 };
        for (int c = 0; c < corners; ++c)
        {
          const long long w = weight(c, i, j, k);
          if (w != 0)
          {
            key.emplace_back(r.NodeIds[c], w);
            for (int a = 0; a < 3; ++a)
            {
              pcoords[a] +=
                static_cast<double>(w) / static_cast<double>(n3) * nodePcoords[3 * c + a];
            }
          }
        }
        r.AddPoint(cell, index(i, j, k), std::move(key), pcoords, weights);
      }
    }
  }
  auto at = [&](int i, int j, int k) { return r.Lattice[index(i, j, k)]; };
  auto addPiece = [&](int type, std::vector<int> ids)
  {
    if (split == vtkHAVSTetrahedralizer::SplitLocalOrder && type != VTK_TETRA)
    {
      // The control: each piece into tetrahedra by its local order.
      static const int hexTets[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 },
        { 0, 7, 4, 6 }, { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
      static const int wedgeTets[3][4] = { { 0, 1, 2, 5 }, { 0, 1, 5, 4 }, { 0, 4, 5, 3 } };
      const int count = type == VTK_HEXAHEDRON ? 6 : 3;
      for (int t = 0; t < count; ++t)
      {
        const int* local = type == VTK_HEXAHEDRON ? hexTets[t] : wedgeTets[t];
        r.Pieces.push_back({ ids[local[0]], ids[local[1]], ids[local[2]], ids[local[3]] });
        r.PieceTypes.push_back(VTK_TETRA);
      }
      return;
    }
    r.Pieces.push_back(std::move(ids));
    r.PieceTypes.push_back(type);
  };
  if (family == HexahedronFamily)
  {
    for (int k = 0; k < n; ++k)
    {
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          addPiece(VTK_HEXAHEDRON,
            { at(i, j, k), at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k), at(i, j, k + 1),
              at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1) });
        }
      }
    }
  }
  else if (family == WedgeFamily)
  {
    for (int k = 0; k < n; ++k)
    {
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i + j < n; ++i)
        {
          addPiece(VTK_WEDGE,
            { at(i, j, k), at(i + 1, j, k), at(i, j + 1, k), at(i, j, k + 1), at(i + 1, j, k + 1),
              at(i, j + 1, k + 1) });
          if (i + j + 2 <= n)
          {
            addPiece(VTK_WEDGE,
              { at(i + 1, j, k), at(i + 1, j + 1, k), at(i, j + 1, k), at(i + 1, j, k + 1),
                at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1) });
          }
        }
      }
    }
  }
  else
  {
    std::array<std::array<int, 3>, 4> root;
    for (int c = 0; c < 4; ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        root[c][a] = cornerBits[c][a] * n;
      }
    }
    std::vector<std::array<std::array<int, 3>, 4>> tets;
    SplitLatticeTetrahedron(root, level, tets);
    for (const auto& t : tets)
    {
      addPiece(VTK_TETRA,
        { at(t[0][0], t[0][1], t[0][2]), at(t[1][0], t[1][1], t[1][2]),
          at(t[2][0], t[2][1], t[2][2]), at(t[3][0], t[3][1], t[3][2]) });
    }
  }
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSTetrahedralizer::RefineHigherOrderCells(
  vtkDataSet* data, int level, Report* report, int split, SourceMap* map)
{
  Report local;
  Report& rep = report ? *report : local;
  auto* input = vtkUnstructuredGrid::SafeDownCast(data);
  level = std::min(level, static_cast<int>(MaximumHigherOrderSubdivision));
  if (!input || level < 1)
  {
    return nullptr;
  }
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  std::vector<vtkIdType> refined;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    const int type = input->GetCellType(c);
    if (CellDimension(type) != 3 || havs_vtk::IsLinearCellType(type))
    {
      continue;
    }
    if (FamilyOf(type) != NotRefined)
    {
      refined.push_back(c);
      rep.CornerPyramids += IsCornerPyramid(type) ? 1 : 0;
    }
    else
    {
      ++rep.UnrefinedNonLinearCells;
    }
  }
  if (refined.empty())
  {
    return nullptr;
  }
  rep.RefinedCells = static_cast<vtkIdType>(refined.size());

  // Each cell's lattice (in parallel: the cells are independent).
  std::vector<RefinedCell> cells(refined.size());
  {
    // A first GetCell on this thread, before the parallel ones (not of a
    // pyramid taken as its corners: VTK has no cell for it).
    const auto first = std::find_if(refined.begin(), refined.end(),
      [input](vtkIdType c) { return !IsCornerPyramid(input->GetCellType(c)); });
    if (first != refined.end())
    {
      vtkNew<vtkGenericCell> cell;
      GetCell(input, *first, cell);
    }
  }
  vtkSMPThreadLocalObject<vtkGenericCell> threadCell;
  vtkSMPThreadLocalObject<vtkPyramid> threadPyramid;
  vtkSMPTools::For(0, static_cast<vtkIdType>(refined.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkGenericCell* cell = threadCell.Local();
      vtkPyramid* corners = threadPyramid.Local();
      for (vtkIdType r = begin; r < end; ++r)
      {
        const int type = input->GetCellType(refined[r]);
        if (IsCornerPyramid(type))
        {
          CornerPyramid(input, refined[r], corners);
          RefineCell(corners, PyramidFamily, level, split, cells[r]);
          continue;
        }
        GetCell(input, refined[r], cell);
        RefineCell(cell, FamilyOf(type), level, split, cells[r]);
      }
    });

  // One output point per key: the input's points keep their ids (a corner
  // is its input point), new points follow.
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(input->GetPoints());
  vtkPointData* inPD = input->GetPointData();
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkPointData* outPD = out->GetPointData();
  outPD->InterpolateAllocate(inPD, inputPoints);
  for (vtkIdType p = 0; p < inputPoints; ++p)
  {
    outPD->CopyData(inPD, p, p);
  }
  std::map<PointKey, vtkIdType> merged;
  vtkNew<vtkIdList> nodeIds;
  if (map)
  {
    map->InputPoints = inputPoints;
    map->StencilOffsets.assign(1, 0);
    map->StencilIds.clear();
    map->StencilWeights.clear();
  }
  std::vector<std::vector<vtkIdType>> outputIds(cells.size());
  for (size_t r = 0; r < cells.size(); ++r)
  {
    const RefinedCell& rc = cells[r];
    const size_t count = rc.Keys.size();
    const size_t nodes = rc.NodeIds.size();
    outputIds[r].resize(count);
    nodeIds->SetNumberOfIds(static_cast<vtkIdType>(nodes));
    for (size_t i = 0; i < nodes; ++i)
    {
      nodeIds->SetId(static_cast<vtkIdType>(i), rc.NodeIds[i]);
    }
    for (size_t p = 0; p < count; ++p)
    {
      const PointKey& key = rc.Keys[p];
      vtkIdType id = -1;
      if (split != SplitUnmerged)
      {
        if (key.size() == 1)
        {
          id = key[0].first; // a corner of the parent
        }
        else
        {
          auto found = merged.find(key);
          if (found != merged.end())
          {
            id = found->second;
          }
        }
      }
      if (id < 0)
      {
        id = points->InsertNextPoint(&rc.Positions[3 * p]);
        outPD->InterpolatePoint(inPD, id, nodeIds, const_cast<double*>(&rc.Weights[nodes * p]));
        ++rep.AddedPoints;
        if (map)
        {
          map->StencilIds.insert(map->StencilIds.end(), rc.NodeIds.begin(), rc.NodeIds.end());
          map->StencilWeights.insert(
            map->StencilWeights.end(), &rc.Weights[nodes * p], &rc.Weights[nodes * p] + nodes);
          map->StencilOffsets.push_back(static_cast<vtkIdType>(map->StencilIds.size()));
        }
        if (split != SplitUnmerged)
        {
          merged.emplace(key, id);
        }
      }
      outputIds[r][p] = id;
    }
  }
  out->SetPoints(points);

  // The cells: the pieces of refined cells, every other cell as it is.
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = out->GetCellData();
  outCD->CopyAllocate(inCD, numberOfCells);
  out->Allocate(numberOfCells);
  size_t next = 0;
  vtkNew<vtkIdList> ids;
  vtkNew<vtkIdList> faceStream;
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    if (next < refined.size() && refined[next] == c)
    {
      const RefinedCell& rc = cells[next];
      for (size_t piece = 0; piece < rc.Pieces.size(); ++piece)
      {
        ids->SetNumberOfIds(static_cast<vtkIdType>(rc.Pieces[piece].size()));
        for (size_t i = 0; i < rc.Pieces[piece].size(); ++i)
        {
          ids->SetId(static_cast<vtkIdType>(i), outputIds[next][rc.Pieces[piece][i]]);
        }
        const vtkIdType id = out->InsertNextCell(rc.PieceTypes[piece], ids);
        outCD->CopyData(inCD, c, id);
      }
      ++next;
      continue;
    }
    input->GetCellPoints(c, ids);
    const vtkIdType id = input->GetCellType(c) == VTK_POLYHEDRON
      ? -1
      : out->InsertNextCell(input->GetCellType(c), ids);
    if (id < 0)
    {
      // The face stream (nfaces, n0, ids..., n1, ids...) through the
      // vtkIdList overload, which every VTK from 9.1 to 9.6 has (the pointer
      // overload is gone in 9.6).
      input->GetFaceStream(c, faceStream);
      const vtkIdType pid = out->InsertNextCell(VTK_POLYHEDRON, ids->GetNumberOfIds(),
        ids->GetPointer(0), faceStream->GetId(0), faceStream->GetPointer(1));
      outCD->CopyData(inCD, c, pid);
      continue;
    }
    outCD->CopyData(inCD, c, id);
  }
  return out;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkHAVSTetrahedralizer::SourceMap::MapPointArray(
  vtkDataArray* points) const
{
  if (!this->Valid || !points || points->GetNumberOfTuples() != this->InputPoints)
  {
    return nullptr;
  }
  const vtkIdType added = static_cast<vtkIdType>(this->StencilOffsets.size()) - 1;
  vtkSmartPointer<vtkDataArray> out;
  out.TakeReference(points->NewInstance());
  out->SetName(points->GetName());
  out->SetNumberOfComponents(points->GetNumberOfComponents());
  out->SetNumberOfTuples(this->InputPoints + added);
  for (vtkIdType p = 0; p < this->InputPoints; ++p)
  {
    out->SetTuple(p, p, points);
  }
  // As vtkPointData::InterpolatePoint does when the cells are refined.
  vtkNew<vtkIdList> ids;
  for (vtkIdType q = 0; q < added; ++q)
  {
    const vtkIdType begin = this->StencilOffsets[q], end = this->StencilOffsets[q + 1];
    ids->SetNumberOfIds(end - begin);
    for (vtkIdType i = begin; i < end; ++i)
    {
      ids->SetId(i - begin, this->StencilIds[i]);
    }
    out->InterpolateTuple(
      this->InputPoints + q, ids, points, const_cast<double*>(this->StencilWeights.data() + begin));
  }
  return out;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataArray> vtkHAVSTetrahedralizer::SourceMap::MapCellArray(
  vtkDataArray* cells) const
{
  if (!this->Valid || !cells)
  {
    return nullptr;
  }
  const vtkIdType count = static_cast<vtkIdType>(this->Cells.size());
  const vtkIdType inputCells = cells->GetNumberOfTuples();
  vtkSmartPointer<vtkDataArray> out;
  out.TakeReference(cells->NewInstance());
  out->SetName(cells->GetName());
  out->SetNumberOfComponents(cells->GetNumberOfComponents());
  out->SetNumberOfTuples(count);
  for (vtkIdType t = 0; t < count; ++t)
  {
    if (this->Cells[t] < 0 || this->Cells[t] >= inputCells)
    {
      return nullptr;
    }
    out->SetTuple(t, this->Cells[t], cells);
  }
  return out;
}

//------------------------------------------------------------------------------
bool vtkHAVSTetrahedralizer::IsTetrahedral(vtkDataSet* data)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid)
  {
    return false;
  }
  if (grid->GetNumberOfCells() == 0)
  {
    return true;
  }
  const vtkSmartPointer<vtkUnsignedCharArray> types = havs_vtk::CellTypeBytes(grid);
  if (!types)
  {
    return false;
  }
  const unsigned char* t = types->GetPointer(0);
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    if (t[c] != VTK_TETRA)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> vtkHAVSTetrahedralizer::Tetrahedralize(
  vtkDataSet* data, Report* report, int higherOrderSubdivision, int split, SourceMap* map)
{
  Report local;
  Report& r = report ? *report : local;
  r = Report();
  if (map)
  {
    *map = SourceMap();
  }
  if (!data)
  {
    return nullptr;
  }
  r.InputCells = data->GetNumberOfCells();
  if (IsTetrahedral(data))
  {
    r.OutputTetrahedra = r.InputCells;
    return vtkUnstructuredGrid::SafeDownCast(data);
  }
  const double start = vtkTimerLog::GetUniversalTime();
  vtkSmartPointer<vtkDataSet> tagged;
  if (map)
  {
    // Every cell's id, carried with the cell data to the tetrahedra it becomes.
    tagged.TakeReference(data->NewInstance());
    tagged->ShallowCopy(data);
    vtkNew<vtkIdTypeArray> source;
    source->SetName(kSourceCell);
    source->SetNumberOfTuples(data->GetNumberOfCells());
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
    {
      source->SetValue(c, c);
    }
    tagged->GetCellData()->AddArray(source);
    map->InputPoints = data->GetNumberOfPoints();
    data = tagged;
  }
  vtkSmartPointer<vtkUnstructuredGrid> pyramidsOnNodes;
  vtkSmartPointer<vtkUnstructuredGrid> valid = WithoutInvalidCells(data, r.InvalidCells);
  if (valid)
  {
    data = valid;
  }
  r.HigherOrderSubdivision =
    std::max(0, std::min(higherOrderSubdivision, static_cast<int>(MaximumHigherOrderSubdivision)));
  // The non-linear cells refined first (counted as the input's cells below).
  vtkSmartPointer<vtkUnstructuredGrid> refined =
    RefineHigherOrderCells(data, r.HigherOrderSubdivision, &r, split, map);
  if (refined)
  {
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
    {
      const int type = data->GetCellType(c);
      if (CellDimension(type) < 3)
      {
        ++r.LowerDimensionCells;
      }
      else if (type != VTK_TETRA)
      {
        ++r.SplitCells;
      }
    }
    data = refined;
  }
  for (vtkIdType c = 0; !refined && c < data->GetNumberOfCells(); ++c)
  {
    const int type = data->GetCellType(c);
    const int dimension = CellDimension(type);
    if (dimension < 3)
    {
      ++r.LowerDimensionCells;
    }
    else if (type != VTK_TETRA)
    {
      ++r.SplitCells;
      r.QuadraticTetrahedra += type == VTK_QUADRATIC_TETRA || type == VTK_LAGRANGE_TETRAHEDRON ||
          type == VTK_BEZIER_TETRAHEDRON
        ? 1
        : 0;
    }
  }
  if (!refined && split == SplitOrdered)
  {
    // Level 0: the 19-node pyramids on their nodes' lattice (VTK's split
    // cracks; the testing hook SplitLocalOrder keeps it: the control), the
    // Lagrange and Bezier pyramids as their corners' pyramid.
    if (auto onNodes = WithPyramidsOnTheirNodes(data, r.CornerPyramids))
    {
      pyramidsOnNodes = onNodes;
      data = pyramidsOnNodes;
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (refined && IsTetrahedral(refined))
  {
    grid = refined; // refined tetrahedra only: nothing left to split
  }
  else if (r.QuadraticTetrahedra > 0)
  {
    // (The testing hook SplitLocalOrder leaves Lagrange and Bezier
    // tetrahedra to VTK's split: the control of their lattice split.)
    grid = SplitWithCanonicalQuadraticTetrahedra(data, split == SplitOrdered);
  }
  if (!grid)
  {
    vtkNew<vtkDataSetTriangleFilter> triangulate;
    triangulate->SetInputData(data);
    triangulate->TetrahedraOnlyOn();
    triangulate->Update();
    grid = triangulate->GetOutput();
  }
  r.Tessellated = true;
  r.OutputTetrahedra = grid->GetNumberOfCells();
  if (map)
  {
    auto* source = vtkIdTypeArray::SafeDownCast(grid->GetCellData()->GetArray(kSourceCell));
    const vtkIdType added = grid->GetNumberOfPoints() - map->InputPoints;
    if (source && source->GetNumberOfTuples() == grid->GetNumberOfCells() &&
      (added == 0 || (refined && map->StencilOffsets.size() == static_cast<size_t>(added) + 1)))
    {
      map->Cells.assign(source->GetPointer(0), source->GetPointer(0) + source->GetNumberOfTuples());
      map->StencilOffsets.resize(static_cast<size_t>(added) + 1, 0);
      map->Valid = true;
    }
    grid->GetCellData()->RemoveArray(kSourceCell);
    if (!map->Valid)
    {
      *map = SourceMap();
    }
  }
  r.Seconds = vtkTimerLog::GetUniversalTime() - start;
  return grid;
}

VTK_ABI_NAMESPACE_END
