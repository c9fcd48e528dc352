/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGeneratedBlock.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @brief   The procedural block of the benchmark (gen1M, gen4M, gen10M), header only.
 *
 * The unit cube in n^3 cubes of 5 tetrahedra (vtkHAVSTetrahedralizer), point
 * scalar "field" = sin(6x) cos(5y) + z. vtkHAVSDataSets::MakeGenerated
 * returns it; the GPU check's case builder (Apps/GPUBench/havs_gpu_cases,
 * which links vtkHAVS::Core alone) makes the same grid on a machine that
 * has no data set, from this one definition.
 */
#ifndef vtkHAVSGeneratedBlock_h
#define vtkHAVSGeneratedBlock_h

#include "vtkDoubleArray.h"
#include "vtkHAVSTetrahedralizer.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <string>

namespace vtkHAVSGeneratedBlock
{
/// The number of cubes along an edge of the block `name` names (gen1M: 60,
/// gen4M: 94, gen10M: 127; "block<N>": N, from 1 to 400, for tests); 0 for
/// any other name.
inline int CubesOf(const std::string& name)
{
  if (name.rfind("block", 0) == 0 && name.size() > 5 &&
    name.find_first_not_of("0123456789", 5) == std::string::npos && name.size() <= 8)
  {
    const int n = std::stoi(name.substr(5));
    return n >= 1 && n <= 400 ? n : 0;
  }
  return name == "gen1M" ? 60 : (name == "gen4M" ? 94 : (name == "gen10M" ? 127 : 0));
}

/// The block of n^3 cubes; `report` as vtkHAVSTetrahedralizer::Tetrahedralize's.
inline vtkSmartPointer<vtkUnstructuredGrid> Make(
  int n, vtkHAVSTetrahedralizer::Report* report = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  vtkNew<vtkDoubleArray> field;
  field->SetName("field");
  field->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    field->SetValue(i, std::sin(6 * x[0]) * std::cos(5 * x[1]) + x[2]);
  }
  image->GetPointData()->SetScalars(field);
  vtkHAVSTetrahedralizer::Report local;
  return vtkHAVSTetrahedralizer::Tetrahedralize(image, report ? report : &local);
}
}

#endif
// VTK-HeaderTest-Exclude: vtkHAVSGeneratedBlock.h
