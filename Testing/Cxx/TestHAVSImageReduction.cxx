/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSImageReduction.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// The level of detail's reduced image (vtkHAVSMapperBase::ImageReduction,
// issue 45), for the mapper named by argument 1 (havs, raycast,
// cellprojection):
// 1. A frame at image scale 0.5 draws the image of a viewport of half the
//    size: its float result against the exact reference of that size, the
//    rays cut at the opaque sphere's depth read at the drawn pixels (the
//    window's depth at the full-size pixel under each drawn pixel's centre):
//    within the exact bound. Control: the reference's full-size pixels
//    (2i, 2j) beside the drawn ones (a quarter of a drawn pixel off) must
//    miss it.
// 2. The composite upsamples it over the viewport (EdgeUpsampling off): a renderer whose viewport
//    is not at the window's origin and not square; the window against the
//    float result upsampled here (bilinear between the drawn pixel centres,
//    over the black background): within 1.5/255, and nothing drawn outside
//    the viewport. Control: nearest-pixel upsampling must miss by more than
//    3/255.
// 3. The controller: a budget of 1 us takes the next frames down to the
//    smallest image (MinimumImageScale); the still budget gives the full
//    image back, bit for bit the image with ImageReduction off. Control: the
//    smallest image differs from it. The edges' mask (4.): asked for in the
//    first reduced frame, dropped once the smallest image misses the budget.
// 4. The edges kept sharp (EdgeUpsampling, on by default): a volume whose
//    opacity is nowhere zero, an opaque sphere in front of part of it, at
//    scale 0.25. Where the exact frame (scale 1) gets nothing from the
//    volume (outside the silhouette, over the sphere), the reduced frame's
//    window is the exact frame's: at most size^2 / 2000 pixels off by more
//    than 1/255; and its RMSE against the exact frame's window at most 0.95
//    times plain bilinear's (3.61 vs 3.97/255 here: inside the silhouette
//    both are bilinear). Control: plain bilinear (EdgeUpsampling off)
//    leaves more than 50 of those pixels off. Mirrored by the volume's
//    matrix, with an opaque sphere inside it: the RMSE bound again. The camera inside the volume
//    (the near plane cuts it, no boundary face in front of the rays): the
//    same window as plain bilinear, bit for bit, and not empty.
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMapperScenes.h"
#include "havsTestProperties.h"
#include "havsTestScenes.h"

#include "vtkHAVSDataSets.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
/// The kept float result and its size.
std::vector<float> Result(vtkHAVSMapperBase* mapper, int size[2])
{
  vtkNew<vtkFloatArray> rgba;
  size[0] = size[1] = 0;
  if (!mapper->GetFloatResult(rgba, size))
  {
    return {};
  }
  return std::vector<float>(rgba->GetPointer(0), rgba->GetPointer(0) + 4 * size[0] * size[1]);
}

/// The RMSE of two windows' RGB (RGBA floats), in units of 1/255.
double RGBError(const std::vector<float>& a, const std::vector<float>& b)
{
  double squares = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    squares += i % 4 != 3 ? std::pow(double(a[i]) - b[i], 2) : 0.0;
  }
  return a.empty() ? 0.0 : 255 * std::sqrt(squares / (3 * (a.size() / 4)));
}

/// The drawn image (w x h, premultiplied) at viewport pixel (x, y) of a
/// viewport W x H: bilinear between the drawn pixel centres (clamped), or the
/// nearest drawn pixel.
float Upsampled(
  const std::vector<float>& image, int w, int h, int W, int H, int x, int y, int c, bool bilinear)
{
  const double sx = (x + 0.5) * w / W - 0.5, sy = (y + 0.5) * h / H - 0.5;
  auto at = [&](int i, int j)
  {
    i = std::min(std::max(i, 0), w - 1);
    j = std::min(std::max(j, 0), h - 1);
    return static_cast<double>(image[4 * (static_cast<size_t>(j) * w + i) + c]);
  };
  if (!bilinear)
  {
    return static_cast<float>(
      at(static_cast<int>(std::floor(sx + 0.5)), static_cast<int>(std::floor(sy + 0.5))));
  }
  const int i = static_cast<int>(std::floor(sx)), j = static_cast<int>(std::floor(sy));
  const double fx = sx - i, fy = sy - j;
  const double a = at(i, j) * (1 - fx) + at(i + 1, j) * fx;
  const double b = at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx;
  return static_cast<float>(a * (1 - fy) + b * fy);
}
}

int TestHAVSImageReduction(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "havs";
  auto grid = vtkHAVSDataSets::MakeBox(10, 10, 10, 0.1, 0.0, 1.0);
  auto property = havstest::MakeRampPropertyFor(grid);

  // 1. Scale 0.5 is the exact image of a half-size viewport.
  {
    const int size = 96, half = size / 2;
    auto mapper = havstest::MakeMapperNamed(name);
    mapper->KeepFloatResultOn();
    mapper->SetImageScale(0.5);
    auto s = havstest::MakeScene(grid, mapper, property, size, size);
    havstest::AddOpaqueSphere(s.Renderer);
    havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
    s.Window->Render();
    int drawn[2];
    const std::vector<float> image = Result(mapper, drawn);
    std::printf("%s: scale 0.5 drew %d x %d (last image scale %.3f)\n", name.c_str(), drawn[0],
      drawn[1], mapper->GetLastImageScale());
    if (!havstest::Check(drawn[0] == half && drawn[1] == half && !image.empty(),
          name + ": scale 0.5 draws a half-size image"))
    {
      return havstest::Result();
    }
    vtkNew<vtkFloatArray> depth, reducedDepth;
    s.Window->GetZbufferData(0, 0, size - 1, size - 1, depth);
    reducedDepth->SetNumberOfValues(static_cast<vtkIdType>(half) * half);
    for (int j = 0; j < half; ++j)
    {
      for (int i = 0; i < half; ++i)
      {
        // The full-size pixel under the drawn pixel's centre, (i + 0.5) * 2.
        reducedDepth->SetValue(j * half + i, depth->GetValue((2 * j + 1) * size + 2 * i + 1));
      }
    }
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    const auto exact =
      havstest::ReferenceImage(grid, property, camera, half, nullptr, reducedDepth);
    const auto full = havstest::ReferenceImage(grid, property, camera, size, nullptr, depth);
    std::vector<float> beside(exact.size());
    for (int j = 0; j < half; ++j)
    {
      for (int i = 0; i < half; ++i)
      {
        std::copy_n(&full[4 * (static_cast<size_t>(2 * j) * size + 2 * i)], 4,
          &beside[4 * (static_cast<size_t>(j) * half + i)]);
      }
    }
    const size_t edge = static_cast<size_t>(half) * half / 2000;
    const auto d = havstest::Compare(image, exact, edge);
    const auto control = havstest::Compare(image, beside, edge);
    havstest::PrintDifference(name + ": scale 0.5 vs the half-size reference", d);
    havstest::PrintDifference(name + ": control, the full-size pixels beside", control);
    havstest::Check(havstest::WithinExactBound(d), name + ": the half-size image is exact");
    havstest::Check(!havstest::WithinExactBound(control),
      name + ": control: pixels a quarter of a drawn pixel off miss the bound");
  }

  // 2. The composite's upsampling, in a viewport off the window's origin.
  {
    const int width = 128, height = 96;
    auto mapper = havstest::MakeMapperNamed(name);
    mapper->KeepFloatResultOn();
    mapper->SetImageScale(0.5);
    mapper->EdgeUpsamplingOff(); // plain bilinear here; 4. keeps the edges
    auto s = havstest::MakeScene(grid, mapper, property, width, height);
    s.Renderer->SetViewport(0.25, 0.125, 1.0, 1.0);
    s.Renderer->SetBackground(0.0, 0.0, 0.0);
    havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
    s.Window->Render();
    int W = 0, H = 0, X = 0, Y = 0;
    s.Renderer->GetTiledSizeAndOrigin(&W, &H, &X, &Y);
    int drawn[2];
    const std::vector<float> image = Result(mapper, drawn);
    const std::vector<float> window = havstest::ReadRGBA(s.Window);
    double worst = 0.0, worstNearest = 0.0, outside = 0.0;
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        const size_t p = 4 * (static_cast<size_t>(y) * width + x);
        const bool in = x >= X && x < X + W && y >= Y && y < Y + H;
        for (int c = 0; c < 3; ++c)
        {
          if (!in)
          {
            outside = std::max(outside, static_cast<double>(window[p + c]));
            continue;
          }
          const double b = Upsampled(image, drawn[0], drawn[1], W, H, x - X, y - Y, c, true);
          const double n = Upsampled(image, drawn[0], drawn[1], W, H, x - X, y - Y, c, false);
          worst = std::max(worst, std::fabs(window[p + c] - std::min(1.0, b)));
          worstNearest = std::max(worstNearest, std::fabs(window[p + c] - std::min(1.0, n)));
        }
      }
    }
    std::printf("%s: viewport %d x %d at (%d, %d) drawn %d x %d: window vs bilinear %.2f/255, "
                "vs nearest %.2f/255, outside the viewport %.2f/255\n",
      name.c_str(), W, H, X, Y, drawn[0], drawn[1], 255 * worst, 255 * worstNearest, 255 * outside);
    havstest::Check(drawn[0] == W / 2 && drawn[1] == H / 2, name + ": half the viewport drawn");
    havstest::Check(worst <= 1.5 / 255, name + ": the composite upsamples bilinearly");
    havstest::Check(outside == 0.0, name + ": nothing is drawn outside the viewport");
    havstest::Check(worstNearest > 3.0 / 255, name + ": control: nearest upsampling misses");
  }

  // 3. The controller: a tiny budget, then the still one.
  {
    const int size = 96;
    auto mapper = havstest::MakeMapperNamed(name);
    mapper->KeepFloatResultOn();
    auto s = havstest::MakeScene(grid, mapper, property, size, size);
    havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
    s.Window->Render();
    int drawn[2];
    mapper->SetLevelOfDetailTargetSeconds(1.0e-6);
    double smallest = 1.0;
    std::vector<bool> edges;
    for (int i = 0; i < 8; ++i)
    {
      s.Window->Render();
      smallest = std::min(smallest, mapper->GetLastImageScale());
      edges.push_back(mapper->GetLastEdgeUpsampling());
    }
    std::printf("%s: the edges' mask in the 8 frames:", name.c_str());
    for (bool e : edges)
    {
      std::printf(" %d", e ? 1 : 0);
    }
    std::printf("\n");
    havstest::Check(edges.front() && !edges.back(),
      name + ": the edges' mask is dropped once the smallest image misses the budget");
    const std::vector<float> reduced = Result(mapper, drawn);
    std::printf("%s: a 1 us budget: image scale down to %.3f (%d x %d)\n", name.c_str(), smallest,
      drawn[0], drawn[1]);
    havstest::Check(smallest == mapper->GetMinimumImageScale() && drawn[0] == 10,
      name + ": a 1 us budget draws the smallest image");
    mapper->SetLevelOfDetailTargetSeconds(0.0); // VTK's allocated time: the still rate
    s.Window->Render();
    const std::vector<float> still = Result(mapper, drawn);
    const double stillScale = mapper->GetLastImageScale();
    mapper->ImageReductionOff();
    s.Window->Render();
    const std::vector<float> off = Result(mapper, drawn);
    havstest::Check(stillScale == 1.0 && still == off && drawn[0] == size,
      name + ": the still budget gives the full image back, bit for bit");
    havstest::Check(reduced.size() != off.size(), name + ": control: the smallest image differs");
  }

  // 4. The edges kept sharp.
  {
    const int size = 96;
    vtkNew<vtkVolumeProperty> dense;
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.3);
    opacity->AddPoint(1.0, 0.8);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.2, 0.4, 1.0);
    color->AddRGBPoint(1.0, 1.0, 0.6, 0.1);
    dense->SetScalarOpacity(opacity);
    dense->SetColor(color);
    dense->SetScalarOpacityUnitDistance(0.5);
    auto mapper = havstest::MakeMapperNamed(name);
    mapper->KeepFloatResultOn();
    auto s = havstest::MakeScene(grid, mapper, dense, size, size);
    s.Renderer->SetBackground(0.0, 0.0, 0.0);
    havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
    // An opaque sphere between the eye and the box, over part of its silhouette.
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    double eye[3], focal[3], toEye[3], right[3], up[3], centre[3];
    camera->GetPosition(eye);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    vtkMath::Subtract(eye, focal, toEye);
    vtkMath::Cross(up, toEye, right);
    vtkMath::Normalize(right);
    for (int i = 0; i < 3; ++i)
    {
      centre[i] = focal[i] + 0.4 * toEye[i] + 0.45 * right[i];
    }
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(centre);
    sphere->SetRadius(0.2);
    sphere->SetThetaResolution(32);
    sphere->SetPhiResolution(32);
    vtkNew<vtkPolyDataMapper> sphereMapper;
    sphereMapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> sphereActor;
    sphereActor->SetMapper(sphereMapper);
    s.Renderer->AddActor(sphereActor);
    s.Renderer->ResetCameraClippingRange();
    auto windowAt = [&](double scale, bool edges)
    {
      mapper->SetImageScale(scale);
      mapper->SetEdgeUpsampling(edges);
      s.Window->Render();
      return havstest::ReadRGBA(s.Window);
    };
    const std::vector<float> exactWindow = windowAt(1.0, true);
    int drawn[2];
    const std::vector<float> exact = Result(mapper, drawn);
    const std::vector<float> edges = windowAt(0.25, true);
    havstest::Check(mapper->GetLastEdgeUpsampling(), name + ": a reduced frame asks for the mask");
    const std::vector<float> bilinear = windowAt(0.25, false);
    size_t empty = 0, offEdges = 0, offBilinear = 0;
    for (size_t p = 0; p < static_cast<size_t>(size) * size; ++p)
    {
      double e = 0.0, b = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        e = std::max(e, std::fabs(double(edges[4 * p + c]) - exactWindow[4 * p + c]));
        b = std::max(b, std::fabs(double(bilinear[4 * p + c]) - exactWindow[4 * p + c]));
      }
      if (p < exact.size() / 4 && exact[4 * p + 3] <= 1.0e-7f)
      {
        ++empty;
        offEdges += e > 1.0 / 255 ? 1 : 0;
        offBilinear += b > 1.0 / 255 ? 1 : 0;
      }
    }
    const double rmseEdges = RGBError(edges, exactWindow);
    const double rmseBilinear = RGBError(bilinear, exactWindow);
    std::printf("%s: scale 0.25, %zu pixels empty in the exact frame: off by more than 1/255 "
                "with the edges kept %zu, plain bilinear %zu; RMSE against the exact frame "
                "%.2f/255 vs %.2f/255\n",
      name.c_str(), empty, offEdges, offBilinear, rmseEdges, rmseBilinear);
    havstest::Check(empty > static_cast<size_t>(size) * size / 4 &&
        offEdges <= static_cast<size_t>(size) * size / 2000,
      name + ": where the exact frame gets nothing from the volume, the reduced frame neither");
    havstest::Check(rmseEdges <= 0.95 * rmseBilinear,
      name + ": the edges kept sharp bring the reduced frame nearer the exact one");
    havstest::Check(offBilinear > 50, name + ": control: plain bilinear blurs the edges");

    // Mirrored by the volume's matrix (the mask's front faces turn clockwise),
    // an opaque sphere inside: the volume in front of it is kept.
    s.Renderer->RemoveActor(sphereActor);
    havstest::AddOpaqueSphere(s.Renderer);
    s.Volume->SetOrigin(0.5, 0.5, 0.5);
    s.Volume->SetScale(-1.0, 1.0, 1.0);
    havstest::PlaceCamera(s.Renderer, 25.0, 15.0, false);
    const std::vector<float> mirroredExact = windowAt(1.0, true);
    const std::vector<float> mirroredEdges = windowAt(0.25, true);
    const std::vector<float> mirroredBilinear = windowAt(0.25, false);
    const double mirroredEdgesRMSE = RGBError(mirroredEdges, mirroredExact);
    const double mirroredBilinearRMSE = RGBError(mirroredBilinear, mirroredExact);
    std::printf("%s: mirrored, an opaque sphere inside, scale 0.25: RMSE against the exact frame "
                "%.2f/255 with the edges kept, %.2f/255 plain bilinear\n",
      name.c_str(), mirroredEdgesRMSE, mirroredBilinearRMSE);
    havstest::Check(mirroredEdgesRMSE <= 0.95 * mirroredBilinearRMSE,
      name + ": mirrored, the edges kept sharp bring the reduced frame nearer the exact one");
    s.Volume->SetScale(1.0, 1.0, 1.0);

    // The camera inside: no mask (plain bilinear), the volume drawn.
    havstest::PlaceCameraInside(s.Renderer, grid, true);
    const std::vector<float> insideEdges = windowAt(0.25, true);
    const std::vector<float> insideBilinear = windowAt(0.25, false);
    double brightest = 0.0;
    for (size_t p = 0; p < insideEdges.size(); p += 4)
    {
      brightest = std::max(brightest, static_cast<double>(insideEdges[p] + insideEdges[p + 2]));
    }
    std::printf("%s: the camera inside, scale 0.25: %s plain bilinear's window, brightest %.3f\n",
      name.c_str(), insideEdges == insideBilinear ? "the same as" : "not", brightest);
    havstest::Check(insideEdges == insideBilinear && brightest > 0.1,
      name + ": with the camera inside, the reduced frame is plain bilinear's");
  }
  return havstest::Result();
}
