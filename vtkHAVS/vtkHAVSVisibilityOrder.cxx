/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVisibilityOrder.cxx

=========================================================================*/
#include "vtkHAVSVisibilityOrder.h"

#include "vtkHAVSFaceSet.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <deque>
#include <limits>

vtkStandardNewMacro(vtkHAVSVisibilityOrder);

namespace
{
using Key = std::array<uint32_t, 3>;

Key SortedKey(uint32_t a, uint32_t b, uint32_t c)
{
  Key k = { a, b, c };
  std::sort(k.begin(), k.end());
  return k;
}
}

//------------------------------------------------------------------------------
bool vtkHAVSVisibilityOrder::Build(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid)
{
  this->FaceCells.clear();
  this->FacePlanes.clear();
  this->CellFaces.clear();
  this->Order.clear();
  if (!faces || !grid || !grid->GetPoints())
  {
    vtkErrorMacro("Build needs a face set and its grid.");
    return false;
  }
  const std::vector<uint32_t>& vertices = faces->GetFaceVertices();
  const std::vector<uint32_t>& tets = faces->GetTetrahedra();
  const size_t numberOfFaces = vertices.size() / 3;
  const size_t numberOfTets = tets.size() / 4;

  // Faces by their sorted point ids.
  std::vector<std::pair<Key, uint32_t>> keys(numberOfFaces);
  for (size_t f = 0; f < numberOfFaces; ++f)
  {
    keys[f] = { SortedKey(vertices[3 * f], vertices[3 * f + 1], vertices[3 * f + 2]),
      static_cast<uint32_t>(f) };
  }
  std::sort(keys.begin(), keys.end());

  this->FaceCells.assign(2 * numberOfFaces, -1);
  this->CellFaces.resize(4 * numberOfTets);
  std::vector<uint32_t> farPoint(numberOfFaces, 0); // cell 0's vertex off the face
  for (size_t t = 0; t < numberOfTets; ++t)
  {
    const uint32_t* p = &tets[4 * t];
    for (int j = 0; j < 4; ++j)
    {
      const Key key = SortedKey(p[(j + 1) % 4], p[(j + 2) % 4], p[(j + 3) % 4]);
      const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, 0u));
      if (it == keys.end() || it->first != key)
      {
        vtkErrorMacro("A face of tetrahedron " << t << " is not in the face set.");
        this->FaceCells.clear();
        return false;
      }
      const uint32_t f = it->second;
      this->CellFaces[4 * t + j] = f;
      if (this->FaceCells[2 * f] < 0)
      {
        this->FaceCells[2 * f] = static_cast<int64_t>(t);
        farPoint[f] = p[j];
      }
      else
      {
        this->FaceCells[2 * f + 1] = static_cast<int64_t>(t);
      }
    }
  }

  // Planes, oriented away from cell 0 (outward for a boundary face).
  vtkPoints* points = grid->GetPoints();
  this->FacePlanes.resize(4 * numberOfFaces);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType f = begin; f < end; ++f)
    {
      double v[3][3], x[3];
      for (int i = 0; i < 3; ++i)
      {
        points->GetPoint(vertices[3 * f + i], v[i]);
      }
      points->GetPoint(farPoint[f], x);
      const double e1[3] = { v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2] };
      const double e2[3] = { v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2] };
      double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0] };
      double d = -(n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2]);
      if (n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + d > 0.0)
      {
        n[0] = -n[0];
        n[1] = -n[1];
        n[2] = -n[2];
        d = -d;
      }
      double* plane = &this->FacePlanes[4 * f];
      plane[0] = n[0];
      plane[1] = n[1];
      plane[2] = n[2];
      plane[3] = d;
    }
  });
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::Sort(const double eye[3], const double direction[3], bool parallel)
{
  const double start = vtkTimerLog::GetUniversalTime();
  const size_t numberOfFaces = this->FacePlanes.size() / 4;
  const size_t numberOfTets = this->CellFaces.size() / 4;
  this->Order.clear();
  this->Order.reserve(numberOfFaces);
  this->NumberOfCycleBreaks = 0;

  // Each face's back cell: the one the ray enters through it (-1: it leaves
  // the mesh there). cell 1 lies on the positive side of the plane.
  std::vector<int64_t> back(numberOfFaces);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numberOfFaces), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType f = begin; f < end; ++f)
    {
      const double* p = &this->FacePlanes[4 * f];
      const double side = parallel
        ? -(p[0] * direction[0] + p[1] * direction[1] + p[2] * direction[2])
        : p[0] * eye[0] + p[1] * eye[1] + p[2] * eye[2] + p[3];
      back[f] = side > 0.0 ? this->FaceCells[2 * f] : this->FaceCells[2 * f + 1];
    }
  });
  std::vector<int32_t> waiting(numberOfTets, 0); // cells in front not visited yet
  for (size_t f = 0; f < numberOfFaces; ++f)
  {
    if (back[f] >= 0 && this->FaceCells[2 * f + 1] >= 0)
    {
      ++waiting[static_cast<size_t>(back[f])];
    }
  }
  std::deque<uint32_t> ready;
  for (size_t t = 0; t < numberOfTets; ++t)
  {
    if (waiting[t] == 0)
    {
      ready.push_back(static_cast<uint32_t>(t));
    }
  }
  std::vector<uint8_t> visited(numberOfTets, 0);
  size_t visitedCount = 0;
  size_t scan = 0;
  while (visitedCount < numberOfTets)
  {
    if (ready.empty())
    {
      // A cycle: take the unvisited cell with the fewest cells still in front.
      size_t best = numberOfTets;
      for (size_t t = 0; t < numberOfTets; ++t)
      {
        if (!visited[(scan + t) % numberOfTets] &&
          (best == numberOfTets || waiting[(scan + t) % numberOfTets] < waiting[best]))
        {
          best = (scan + t) % numberOfTets;
        }
      }
      scan = best;
      ready.push_back(static_cast<uint32_t>(best));
      ++this->NumberOfCycleBreaks;
    }
    const uint32_t c = ready.front();
    ready.pop_front();
    if (visited[c])
    {
      continue;
    }
    visited[c] = 1;
    ++visitedCount;
    const uint32_t* cellFaces = &this->CellFaces[4 * static_cast<size_t>(c)];
    // Entries (the faces behind which c lies), then the mesh's exits from c.
    for (int j = 0; j < 4; ++j)
    {
      if (back[cellFaces[j]] == static_cast<int64_t>(c))
      {
        this->Order.push_back(cellFaces[j]);
      }
    }
    for (int j = 0; j < 4; ++j)
    {
      const uint32_t f = cellFaces[j];
      if (back[f] < 0)
      {
        this->Order.push_back(f);
      }
      else if (back[f] != static_cast<int64_t>(c))
      {
        // c is in front of the cell behind f.
        const size_t behind = static_cast<size_t>(back[f]);
        if (--waiting[behind] == 0 && !visited[behind])
        {
          ready.push_back(static_cast<uint32_t>(behind));
        }
      }
    }
  }
  this->LastSortSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkHAVSVisibilityOrder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Faces: " << this->FacePlanes.size() / 4
     << ", tetrahedra: " << this->CellFaces.size() / 4 << "\n";
  os << indent << "NumberOfCycleBreaks: " << this->NumberOfCycleBreaks << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
}
