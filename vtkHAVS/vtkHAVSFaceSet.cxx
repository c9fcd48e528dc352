/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSet.cxx

=========================================================================*/
#include "vtkHAVSFaceSet.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkHAVSFaceSet);

namespace
{
/// A face instance: sorted ids (the key), the ids in the cell's order, the
/// cell's fourth point (to orient it outward).
struct FaceInstance
{
  std::array<uint32_t, 3> Key;
  std::array<uint32_t, 3> Ids;
  uint32_t Opposite;

  bool operator<(const FaceInstance& other) const { return this->Key < other.Key; }
};

double Distance(const double a[3], const double b[3])
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
}
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSet::Clear()
{
  this->Vertices.clear();
  this->Boundary.clear();
  this->Centroids.clear();
  this->NumberOfBoundaryFaces = 0;
  this->NumberOfTetrahedra = 0;
  this->NumberOfSkippedCells = 0;
  this->NumberOfDegenerateTetrahedra = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->LongestEdge = 0.0;
  this->CentroidOrigin[0] = this->CentroidOrigin[1] = this->CentroidOrigin[2] = 0.0;
}

//------------------------------------------------------------------------------
bool vtkHAVSFaceSet::Build(vtkUnstructuredGrid* grid)
{
  this->Clear();
  this->BuildTime.Modified();
  if (!grid || !grid->GetPoints() || grid->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("No grid or no points.");
    return false;
  }
  if (grid->GetNumberOfPoints() >= static_cast<vtkIdType>(std::numeric_limits<uint32_t>::max()))
  {
    vtkErrorMacro("Too many points (" << grid->GetNumberOfPoints() << ") for 32-bit ids.");
    return false;
  }
  vtkPoints* points = grid->GetPoints();
  double bounds[6];
  points->GetBounds(bounds);
  for (int i = 0; i < 3; ++i)
  {
    this->CentroidOrigin[i] = 0.5 * (bounds[2 * i] + bounds[2 * i + 1]);
  }
  const double* origin = this->CentroidOrigin;

  // Face instances of the usable tetrahedra.
  std::vector<FaceInstance> instances;
  instances.reserve(4 * static_cast<size_t>(grid->GetNumberOfCells()));
  static const int faceOfTet[4][4] = { { 0, 1, 2, 3 }, { 0, 1, 3, 2 }, { 0, 2, 3, 1 },
    { 1, 2, 3, 0 } };
  auto cells = vtk::TakeSmartPointer(grid->GetCells()->NewIterator());
  vtkIdType cellId = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cellId)
  {
    vtkIdType npts;
    const vtkIdType* pts;
    cells->GetCurrentCell(npts, pts);
    if (grid->GetCellType(cellId) != VTK_TETRA || npts != 4)
    {
      ++this->NumberOfSkippedCells;
      continue;
    }
    double x[4][3];
    for (int i = 0; i < 4; ++i)
    {
      points->GetPoint(pts[i], x[i]);
    }
    double longest = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      for (int j = i + 1; j < 4; ++j)
      {
        longest = std::max(longest, Distance(x[i], x[j]));
      }
    }
    double e1[3], e2[3], e3[3], c[3];
    for (int k = 0; k < 3; ++k)
    {
      e1[k] = x[1][k] - x[0][k];
      e2[k] = x[2][k] - x[0][k];
      e3[k] = x[3][k] - x[0][k];
    }
    vtkMath::Cross(e1, e2, c);
    const double volume6 = vtkMath::Dot(c, e3);
    const bool repeated = pts[0] == pts[1] || pts[0] == pts[2] || pts[0] == pts[3] ||
      pts[1] == pts[2] || pts[1] == pts[3] || pts[2] == pts[3];
    if (repeated || !(std::fabs(volume6) / 6.0 > 1e-12 * longest * longest * longest))
    {
      ++this->NumberOfDegenerateTetrahedra;
      continue;
    }
    ++this->NumberOfTetrahedra;
    this->LongestEdge = std::max(this->LongestEdge, longest);
    for (const auto& f : faceOfTet)
    {
      FaceInstance inst;
      inst.Ids = { static_cast<uint32_t>(pts[f[0]]), static_cast<uint32_t>(pts[f[1]]),
        static_cast<uint32_t>(pts[f[2]]) };
      inst.Key = inst.Ids;
      std::sort(inst.Key.begin(), inst.Key.end());
      inst.Opposite = static_cast<uint32_t>(pts[f[3]]);
      instances.push_back(inst);
    }
  }
  if (this->NumberOfTetrahedra == 0)
  {
    vtkErrorMacro("No usable tetrahedra (" << this->NumberOfSkippedCells << " other cells, "
                                           << this->NumberOfDegenerateTetrahedra
                                           << " degenerate tetrahedra).");
    const vtkIdType skipped = this->NumberOfSkippedCells;
    const vtkIdType degenerate = this->NumberOfDegenerateTetrahedra;
    this->Clear();
    this->NumberOfSkippedCells = skipped;
    this->NumberOfDegenerateTetrahedra = degenerate;
    return false;
  }

  vtkSMPTools::Sort(instances.begin(), instances.end());

  // Runs of equal keys are one face.
  std::vector<size_t> runStarts;
  runStarts.reserve(instances.size() / 2 + 1);
  for (size_t i = 0; i < instances.size(); ++i)
  {
    if (i == 0 || instances[i].Key != instances[i - 1].Key)
    {
      runStarts.push_back(i);
    }
  }
  const size_t numFaces = runStarts.size();
  runStarts.push_back(instances.size());
  this->Vertices.resize(3 * numFaces);
  this->Boundary.resize(numFaces);
  this->Centroids.resize(3 * numFaces);

  vtkSMPTools::For(0, static_cast<vtkIdType>(numFaces), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType f = begin; f < end; ++f)
    {
      const FaceInstance& inst = instances[runStarts[f]];
      const size_t uses = runStarts[f + 1] - runStarts[f];
      std::array<uint32_t, 3> ids = inst.Ids;
      double p[3][3], o[3];
      for (int i = 0; i < 3; ++i)
      {
        points->GetPoint(ids[i], p[i]);
      }
      if (uses == 1)
      {
        // Outward: the normal must point away from the opposite vertex.
        points->GetPoint(inst.Opposite, o);
        double a[3], b[3], n[3], d[3];
        for (int k = 0; k < 3; ++k)
        {
          a[k] = p[1][k] - p[0][k];
          b[k] = p[2][k] - p[0][k];
          d[k] = o[k] - p[0][k];
        }
        vtkMath::Cross(a, b, n);
        if (vtkMath::Dot(n, d) > 0.0)
        {
          std::swap(ids[1], ids[2]);
        }
      }
      this->Boundary[f] = uses == 1 ? 1 : 0;
      for (int i = 0; i < 3; ++i)
      {
        this->Vertices[3 * f + i] = ids[i];
        this->Centroids[3 * f + i] =
          static_cast<float>((p[0][i] + p[1][i] + p[2][i]) / 3.0 - origin[i]);
      }
    }
  });
  for (size_t f = 0; f < numFaces; ++f)
  {
    const size_t uses = runStarts[f + 1] - runStarts[f];
    this->NumberOfBoundaryFaces += uses == 1 ? 1 : 0;
    this->NumberOfNonManifoldFaces += uses > 2 ? 1 : 0;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSFaceSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces: " << this->GetNumberOfFaces() << " (" << this->NumberOfBoundaryFaces
     << " boundary, " << this->NumberOfNonManifoldFaces << " non-manifold)\n";
  os << indent << "Tetrahedra: " << this->NumberOfTetrahedra << " (skipped cells "
     << this->NumberOfSkippedCells << ", degenerate " << this->NumberOfDegenerateTetrahedra
     << ")\n";
  os << indent << "LongestEdge: " << this->LongestEdge << "\n";
}
