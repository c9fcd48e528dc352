// vtkHAVSFaceSorter: keys ascend along the order (recomputed in double),
// perspective and parallel; the volume matrix enters the key; an unchanged
// camera reuses the sort, a moved one re-sorts; block reversal moves each face
// at most block - 1 places.
#include "vtkHAVSTestUtilities.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdlib>

namespace
{
double Key(vtkHAVSFaceSet* faces, vtkIdType f, const double m[16], const double eye[3],
  const double dir[3], bool parallel)
{
  const float* c = &faces->GetCentroids()[3 * f];
  const double* o = faces->GetCentroidOrigin();
  const double p[3] = { c[0] + o[0], c[1] + o[1], c[2] + o[2] };
  double w[3];
  for (int r = 0; r < 3; ++r)
  {
    w[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3] - eye[r];
  }
  return parallel ? w[0] * dir[0] + w[1] * dir[1] + w[2] * dir[2]
                  : std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
}

bool Ascending(vtkHAVSFaceSet* faces, vtkHAVSFaceSorter* sorter, const double m[16],
  const double eye[3], const double dir[3], bool parallel)
{
  const auto& order = sorter->GetOrder();
  if (static_cast<vtkIdType>(order.size()) != faces->GetNumberOfFaces())
  {
    return false;
  }
  for (size_t i = 1; i < order.size(); ++i)
  {
    // float keys: allow their rounding
    const double a = Key(faces, order[i - 1], m, eye, dir, parallel);
    const double b = Key(faces, order[i], m, eye, dir, parallel);
    if (a > b + 1e-5 * std::fabs(b))
    {
      return false;
    }
  }
  return true;
}
}

int main()
{
  auto grid = havstest::MakeBox(6, 5, 4, 0.2, 0.0, 1.0);
  vtkNew<vtkHAVSFaceSet> faces;
  faces->Build(grid);
  vtkNew<vtkHAVSFaceSorter> sorter;
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const double eye[3] = { 3.0, -2.0, 4.0 };
  const double dir[3] = { -0.5773502691896258, 0.5773502691896258, -0.5773502691896258 };

  havstest::Check(sorter->Sort(faces, identity, eye, dir, false), "first sort sorts");
  havstest::Check(Ascending(faces, sorter, identity, eye, dir, false), "perspective order");
  const vtkIdType sorts = sorter->GetNumberOfSorts();
  havstest::Check(!sorter->Sort(faces, identity, eye, dir, false) &&
      sorter->GetNumberOfSorts() == sorts,
    "an unchanged camera reuses the sort");
  const double eye2[3] = { 3.0, -2.0, 4.5 };
  havstest::Check(sorter->Sort(faces, identity, eye2, dir, false), "a moved eye re-sorts");

  havstest::Check(sorter->Sort(faces, identity, eye, dir, true), "parallel sorts");
  havstest::Check(Ascending(faces, sorter, identity, eye, dir, true), "parallel order");

  // Scale and translate: the key follows the matrix.
  const double scaled[16] = { 1, 0, 0, 0.5, 0, 3, 0, -1, 0, 0, 0.5, 2, 0, 0, 0, 1 };
  sorter->Sort(faces, scaled, eye, dir, false);
  havstest::Check(Ascending(faces, sorter, scaled, eye, dir, false), "matrix order");
  const std::vector<uint32_t> exact = sorter->GetOrder();
  // Negative control: the identity order is not ascending under the scaled matrix.
  sorter->Sort(faces, identity, eye, dir, false);
  havstest::Check(!Ascending(faces, sorter, scaled, eye, dir, false),
    "negative control: the unscaled order fails the scaled keys");

  // Block reversal: each face at most block - 1 places from its sorted place.
  sorter->SetBlockReversal(7);
  sorter->Sort(faces, scaled, eye, dir, false);
  std::vector<size_t> place(exact.size());
  for (size_t i = 0; i < exact.size(); ++i)
  {
    place[exact[i]] = i;
  }
  size_t maxMove = 0;
  for (size_t i = 0; i < exact.size(); ++i)
  {
    const size_t p = place[sorter->GetOrder()[i]];
    maxMove = std::max(maxMove, p > i ? p - i : i - p);
  }
  havstest::Check(maxMove == 6, "block reversal of 7 moves faces by up to 6 places");
  std::cout << faces->GetNumberOfFaces() << " faces, last sort " << sorter->GetLastSortSeconds()
            << " s" << std::endl;
  return havstest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
