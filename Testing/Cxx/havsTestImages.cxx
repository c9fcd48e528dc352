/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestImages.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestImages.h"

#include "vtkFloatArray.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSImageMetrics.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace havstest
{
namespace
{
std::string EnvOr(const char* name, const char* fallback)
{
  const char* v = std::getenv(name);
  return (v && *v) ? std::string(v) : std::string(fallback);
}
}

std::string OutputDir()
{
  return EnvOr("HAVS_TEST_OUTPUT_DIR", ".");
}

std::string BaselineDir()
{
  return EnvOr("HAVS_BASELINE_DIR", "Testing/Baseline");
}

std::vector<float> ReadRGBA(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkFloatArray> data;
  window->GetRGBAPixelData(0, 0, size[0] - 1, size[1] - 1, 0, data);
  std::vector<float> out(data->GetPointer(0), data->GetPointer(0) + 4 * size[0] * size[1]);
  return out;
}

std::vector<float> FloatResult(vtkAbstractVolumeMapper* mapper)
{
  vtkNew<vtkFloatArray> result;
  int size[2] = { 0, 0 };
  auto* havs = vtkHAVSVolumeMapper::SafeDownCast(mapper);
  auto* cells = vtkHAVSCellProjectionMapper::SafeDownCast(mapper);
  auto* rays = vtkHAVSRayCastMapper::SafeDownCast(mapper);
  if (!(havs ? havs->GetFloatResult(result, size)
             : (cells ? cells->GetFloatResult(result, size)
                      : (rays ? rays->GetFloatResult(result, size) : false))))
  {
    return {};
  }
  return std::vector<float>(result->GetPointer(0), result->GetPointer(0) + 4 * size[0] * size[1]);
}

ImageDifference Compare(
  const std::vector<float>& a, const std::vector<float>& b, size_t ignoreWorst)
{
  vtkNew<vtkHAVSImageMetrics> metrics;
  metrics->SetIgnoreWorstPixels(static_cast<vtkIdType>(ignoreWorst));
  metrics->Compare(a, b);
  ImageDifference d;
  d.RMSE = metrics->GetRMSE();
  d.Max = metrics->GetMaxAbsError();
  d.FractionOver1 = metrics->GetFractionOver1();
  d.FractionOver4 = metrics->GetFractionOver4();
  return d;
}

bool AllFinite(const std::vector<float>& values)
{
  for (float v : values)
  {
    if (!std::isfinite(v))
    {
      return false;
    }
  }
  return true;
}

void WritePNG(const std::vector<float>& rgba, int width, int height, const std::string& name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < rgba.size(); ++i)
  {
    const float v = std::isfinite(rgba[i]) ? std::min(std::max(rgba[i], 0.0f), 1.0f) : 0.0f;
    out[i] = static_cast<unsigned char>(v * 255.0f + 0.5f);
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((OutputDir() + "/" + name).c_str());
  writer->Write();
}

void WriteRGB(vtkUnsignedCharArray* rgb, int width, int height, const std::string& name)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(width, height, 1);
  image->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((OutputDir() + "/" + name).c_str());
  writer->Write();
}

std::vector<float> ReadPNG(const std::string& path, int* width, int* height)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return {};
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  *width = dims[0];
  *height = dims[1];
  const int nc = image->GetNumberOfScalarComponents();
  std::vector<float> out(static_cast<size_t>(dims[0]) * dims[1] * 4, 1.0f);
  auto* in = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t p = 0; p < static_cast<size_t>(dims[0]) * dims[1]; ++p)
  {
    for (int c = 0; c < std::min(nc, 4); ++c)
    {
      out[4 * p + c] = in[nc * p + c] / 255.0f;
    }
  }
  return out;
}
}
