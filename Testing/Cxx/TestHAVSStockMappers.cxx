/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSStockMappers.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// HAVS side by side with VTK's stock unstructured-grid mappers on a real data
// set (argument: bluntfin | loxpost | loxpostvtk), same scene, camera and
// window. The yardstick is vtkUnstructuredGridVolumeRayCastMapper with
// ImageSampleDistance 1, AutoAdjustSampleDistances off and
// vtkUnstructuredGridLinearRayIntegrator, which integrates the piecewise-linear
// transfer functions used here exactly along each cell's segment. HAVS must be
// within the RMSE bound given on the command line (see Testing/README.md for
// why that bound); the same bound with k = 1 and a 4^3 table must FAIL
// (negative control). vtkProjectedTetrahedraMapper and
// vtkUnstructuredGridVolumeZSweepMapper are rendered in the same test and
// their RMSE printed.
#include "vtkHAVSTestUtilities.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdlib>

namespace
{
std::vector<float> RenderWith(vtkUnstructuredGrid* grid, vtkAbstractVolumeMapper* mapper,
  vtkVolumeProperty* property, int size, const std::string& name, double* seconds)
{
  auto scene = havstest::MakeScene(grid, mapper, property, size, size);
  havstest::PlaceCamera(scene.Renderer, 35.0, 25.0, false);
  const double start = vtkTimerLog::GetUniversalTime();
  scene.Window->Render();
  *seconds = vtkTimerLog::GetUniversalTime() - start;
  std::vector<float> rgba = havstest::ReadRGBA(scene.Window);
  havstest::WritePNG(rgba, size, size, name + ".png");
  return rgba;
}
}

int main(int argc, char* argv[])
{
  const std::string dataset = argc > 1 ? argv[1] : "loxpostvtk";
  const double bound = argc > 2 ? std::atof(argv[2]) : 0.02;
  const int size = argc > 3 ? std::atoi(argv[3]) : 128;
  vtkSmartPointer<vtkUnstructuredGrid> grid = havstest::ReadDataSet(dataset);
  if (!havstest::Check(grid && grid->GetNumberOfCells() > 0, "data set read: " + dataset))
  {
    return EXIT_FAILURE;
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  auto property = havstest::MakeRampPropertyFor(grid);
  std::cout << dataset << ": " << grid->GetNumberOfCells() << " tets, scalar range [" << range[0]
            << ", " << range[1] << "], " << size << "^2" << std::endl;

  double t = 0;
  vtkNew<vtkUnstructuredGridVolumeRayCastMapper> raycast;
  raycast->SetImageSampleDistance(1.0);
  raycast->AutoAdjustSampleDistancesOff();
  raycast->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
  const auto reference = RenderWith(grid, raycast, property, size, dataset + "_raycast", &t);
  std::cout << "RayCast (linear integrator): " << t << " s" << std::endl;

  vtkNew<vtkHAVSVolumeMapper> havs;
  havs->SetKBufferSize(14);
  const auto image = RenderWith(grid, havs, property, size, dataset + "_havs", &t);
  const auto d = havstest::Compare(image, reference);
  std::cout << "HAVS k=14 (" << havs->GetActiveKBufferPathName() << "): " << t << " s, RMSE "
            << d.RMSE << ", max " << d.Max << ", pixels > 1/255: " << 100 * d.FractionOver1
            << " %" << std::endl;
  havstest::Check(d.RMSE < bound, "HAVS within the RMSE bound of the ray-cast mapper");

  vtkNew<vtkHAVSVolumeMapper> lists;
  lists->SetKBufferPathToFragmentLists();
  const auto exact = RenderWith(grid, lists, property, size, dataset + "_havs_lists", &t);
  const auto dl = havstest::Compare(exact, reference);
  std::cout << "HAVS fragment lists (exact sort): " << t << " s, RMSE " << dl.RMSE << ", max "
            << dl.Max << std::endl;
  havstest::Check(dl.RMSE < bound, "HAVS (exact per-pixel sort) within the bound");

  // Negative control: k = 1 with a 4^3 table must miss the bound.
  vtkNew<vtkHAVSVolumeMapper> poor;
  poor->SetKBufferSize(1);
  poor->SetTableScalarResolution(4);
  poor->SetTableLengthResolution(4);
  const auto bad = RenderWith(grid, poor, property, size, dataset + "_havs_k1_table4", &t);
  const auto db = havstest::Compare(bad, reference);
  std::cout << "HAVS k=1, 4^3 table (negative control): RMSE " << db.RMSE << std::endl;
  havstest::Check(db.RMSE > bound, "negative control: k = 1 and a 4^3 table miss the bound");

  vtkNew<vtkProjectedTetrahedraMapper> pt;
  const auto ptImage = RenderWith(grid, pt, property, size, dataset + "_pt", &t);
  const auto dp = havstest::Compare(ptImage, reference);
  std::cout << "ProjectedTetrahedra: " << t << " s, RMSE " << dp.RMSE << ", max " << dp.Max
            << std::endl;

  vtkNew<vtkUnstructuredGridVolumeZSweepMapper> zsweep;
  zsweep->SetImageSampleDistance(1.0);
  zsweep->AutoAdjustSampleDistancesOff();
  zsweep->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
  const auto zImage = RenderWith(grid, zsweep, property, size, dataset + "_zsweep", &t);
  const auto dz = havstest::Compare(zImage, reference);
  std::cout << "ZSweep (linear integrator): " << t << " s, RMSE " << dz.RMSE << ", max "
            << dz.Max << std::endl;
  havstest::Check(havstest::AllFinite(ptImage) && havstest::AllFinite(zImage),
    "stock mappers rendered");

  return havstest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
