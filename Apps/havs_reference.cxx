/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_reference.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_reference: the exact reference image and the k-requirement analysis
// (thesis Table 4.2, Fig. 4.7) of a data set, from the command line.
//
//   havs_reference [--dataset bluntfin|loxpost|combustor|loxpostvtk | --input mesh.vtu]
//                  [--size N] [--views 14] [--k-image out.png] [--image out.png]
//                  [--order centroid|mpvo|mpvo-convex|mpvo-ignore]
//
// For each of 14 fixed viewpoints (the 6 axis directions and the 8 cube
// diagonals) it finds every pixel's exact fragments, orders them as
// vtkHAVSVolumeMapper draws them (its centroid sort for that camera, or MPVO
// with the boundary layers, with the convexification, or alone) and
// computes the required k; it prints the totals as a Markdown row. --image
// writes the exact image of the first view, --k-image its required-k image
// (green k <= 2, yellow k <= 6, red k > 6).
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSFaceSorter.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSSoftwareKBuffer.h"
#include "vtkHAVSStandardViews.h"
#include "vtkHAVSVisibilityOrder.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
void WritePNG(vtkDataArray* scalars, int size, const std::string& path)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(size, size, 1);
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
}
}

int main(int argc, char* argv[])
{
  std::string dataset = "bluntfin", input, kImagePath, imagePath, order = "centroid";
  int size = 512, views = 14;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--dataset")
      dataset = next();
    else if (a == "--input")
      input = next();
    else if (a == "--size")
      size = std::max(1, std::atoi(next().c_str()));
    else if (a == "--views")
      views = std::min(14, std::max(1, std::atoi(next().c_str())));
    else if (a == "--k-image")
      kImagePath = next();
    else if (a == "--order")
      order = next();
    else if (a == "--image")
      imagePath = next();
    else
    {
      std::cout << "usage: havs_reference [--dataset bluntfin|loxpost|combustor|loxpostvtk | "
                   "--input mesh.vtu] [--size N] [--views 1..14] [--k-image out.png] "
                   "[--image out.png] [--order centroid|mpvo|mpvo-convex|mpvo-ignore]\n";
      return a == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    input.empty() ? vtkHAVSDataSets::Load(dataset) : vtkHAVSDataSets::ReadFile(input);
  if (!grid || grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
  {
    std::cerr << "havs_reference: could not load a tetrahedral mesh with point scalars\n";
    return EXIT_FAILURE;
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.1, 0.2, 1.0);
  color->AddRGBPoint(range[1], 1.0, 0.3, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[1], 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(grid->GetLength() / 8.0);

  vtkNew<vtkCamera> camera;
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(camera);
  reference->SetSize(size, size);
  vtkNew<vtkHAVSFaceSorter> sorter;
  vtkNew<vtkHAVSVisibilityOrder> mpvo;
  const bool useMPVO = order.compare(0, 4, "mpvo") == 0;
  mpvo->SetNonConvexMethod(order == "mpvo-convex"
      ? vtkHAVSVisibilityOrder::NonConvexConvexification
      : (order == "mpvo-ignore" ? vtkHAVSVisibilityOrder::NonConvexIgnore
                                : vtkHAVSVisibilityOrder::NonConvexBoundaryLayers));
  vtkIdType cycleBreaks = 0;
  double orderSeconds = 0.0;
  vtkNew<vtkHAVSSoftwareKBuffer> analysis;
  vtkNew<vtkIntArray> requiredK;
  vtkNew<vtkUnsignedCharArray> colours;

  vtkIdType fragments = 0, over2 = 0, over6 = 0, over14 = 0;
  int longest = 0, maxK = 0;
  const double start = vtkTimerLog::GetUniversalTime();
  for (int view = 0; view < views; ++view)
  {
    vtkHAVSStandardViews::PlaceCamera(camera, grid, view);
    if (!reference->ComputeFragments())
    {
      return EXIT_FAILURE;
    }
    // The mapper's draw order for this camera (identity volume matrix).
    const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    double eye[3], dop[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(dop);
    if (useMPVO)
    {
      if (view == 0 && !mpvo->Build(reference->GetFaceSet(), grid))
      {
        return EXIT_FAILURE;
      }
      vtkNew<vtkMatrix4x4> toClip;
      toClip->DeepCopy(camera->GetCompositeProjectionTransformMatrix(1.0, -1, 1));
      mpvo->SetViewSampling(toClip->GetData(), size, size);
      mpvo->Sort(eye, dop, false);
      cycleBreaks += mpvo->GetNumberOfCycleBreaks();
      orderSeconds += mpvo->GetLastSortSeconds();
      analysis->SetFaceOrder(mpvo->GetOrder());
    }
    else
    {
      sorter->Invalidate();
      sorter->Sort(reference->GetFaceSet(), identity, eye, dop, false);
      orderSeconds += sorter->GetLastSortSeconds();
      analysis->SetFaceOrder(sorter->GetOrder());
    }
    analysis->Analyze(reference, requiredK, view == 0 ? colours.Get() : nullptr);
    fragments += analysis->GetNumberOfFragments();
    longest = std::max(longest, analysis->GetLongestList());
    maxK = std::max(maxK, analysis->GetMaximumRequiredK());
    over2 += analysis->GetPixelsOverK2();
    over6 += analysis->GetPixelsOverK6();
    over14 += analysis->GetPixelsOverK14();
    if (view == 0)
    {
      if (!kImagePath.empty())
      {
        WritePNG(colours, size, kImagePath);
      }
      if (!imagePath.empty())
      {
        reference->Render();
        vtkNew<vtkUnsignedCharArray> rgb;
        rgb->SetNumberOfComponents(3);
        rgb->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
        for (vtkIdType p = 0; p < static_cast<vtkIdType>(size) * size; ++p)
        {
          for (int c = 0; c < 3; ++c)
          {
            const double v = reference->GetImage()->GetComponent(p, c);
            rgb->SetComponent(p, c, std::round(255.0 * std::min(std::max(v, 0.0), 1.0)));
          }
        }
        WritePNG(rgb, size, imagePath);
      }
    }
  }
  std::printf(
    "| data set | tets | views | size | fragments | longest list | max k | pixels k > 2 | "
    "pixels k > 6 | pixels k > 14 | seconds |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| %s | %lld | %d | %d^2 | %lld | %d | %d | %lld | %lld | %lld | %.1f |\n",
    input.empty() ? dataset.c_str() : input.c_str(),
    static_cast<long long>(grid->GetNumberOfCells()), views, size,
    static_cast<long long>(fragments), longest, maxK, static_cast<long long>(over2),
    static_cast<long long>(over6), static_cast<long long>(over14),
    vtkTimerLog::GetUniversalTime() - start);
  std::printf("(%s draw order, as vtkHAVSVolumeMapper; %.2f ms per view to order the faces; "
              "%lld cycle breaks; SMP backend %s)\n",
    useMPVO ? order.c_str() : "centroid-sorted", 1000.0 * orderSeconds / std::max(views, 1),
    static_cast<long long>(cycleBreaks), vtkSMPTools::GetBackend());
  if (useMPVO)
  {
    std::printf("(mesh %s; %lld imaginary cells, convexified in %.2f s; %lld boundary-layer "
                "relations in the last view, %.2f ms)\n",
      mpvo->IsMeshConvex() ? "convex" : "non-convex",
      static_cast<long long>(mpvo->GetNumberOfImaginaryCells()), mpvo->GetConvexificationSeconds(),
      static_cast<long long>(mpvo->GetNumberOfBoundaryRelations()),
      1000.0 * mpvo->GetLastBoundaryLayerSeconds());
  }
  return EXIT_SUCCESS;
}
