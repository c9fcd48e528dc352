// havs_demo: renders an unstructured mesh with vtkHAVSVolumeMapper and with
// VTK's vtkProjectedTetrahedraMapper, vtkUnstructuredGridVolumeZSweepMapper and
// vtkUnstructuredGridVolumeRayCastMapper swapped into the same pipeline,
// orbiting the camera over N frames. Prints a table (median ms per frame, HAVS
// split into sort / draw / flush, tets/s, image RMSE against the exact
// reference) and writes the first frame of every mapper side by side into a PNG.
// The error is measured against vtkHAVSReferenceRenderer, the exact image
// (double-precision ray/face intersections, each segment integrated to 1e-6),
// on the colour seen in the window (the volume over a black background).
#include "vtkHAVSImageMetrics.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkHAVSRenderWindowFactory.h"
#include "vtkHAVSFrameStatistics.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiBlockPLOT3DReader.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkUnstructuredGridVolumeZSweepMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  std::string Input;
  std::string Plot3DXYZ, Plot3DQ;
  int Plot3DFunction = 100;
  std::string Array;
  int Frames = 8;
  int Width = 256, Height = 256;
  int K = 6;
  std::string Output = "havs_demo.png";
};

void Usage()
{
  std::cout
    << "usage: havs_demo [--input mesh.vtu|mesh.vtk] [--plot3d xyz.bin q.bin [function]]\n"
       "                 [--array name] [--frames N] [--size W H] [--k K] [--output out.png]\n"
       "Without an input, renders the project's default mesh (an analytic field on a\n"
       "tetrahedralized 24^3 block, made here).\n";
}

/// The project's default mesh: three Gaussian blobs on a tetrahedralized block.
vtkSmartPointer<vtkUnstructuredGrid> DefaultMesh()
{
  const int n = 24;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n + 1, n + 1, n + 1);
  image->SetSpacing(1.0 / n, 1.0 / n, 1.0 / n);
  image->SetOrigin(-0.5, -0.5, -0.5);
  vtkNew<vtkDoubleArray> field;
  field->SetName("field");
  field->SetNumberOfTuples(image->GetNumberOfPoints());
  const double centres[3][3] = { { -0.2, -0.1, 0.0 }, { 0.2, 0.15, 0.1 }, { 0.0, 0.1, -0.25 } };
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    double x[3];
    image->GetPoint(i, x);
    double v = 0.0;
    for (const auto& c : centres)
    {
      const double d2 = (x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
        (x[2] - c[2]) * (x[2] - c[2]);
      v += std::exp(-d2 / 0.03);
    }
    field->SetValue(i, v);
  }
  image->GetPointData()->SetScalars(field);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(image);
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const Options& o)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (!o.Plot3DXYZ.empty())
  {
    vtkNew<vtkMultiBlockPLOT3DReader> reader;
    reader->SetXYZFileName(o.Plot3DXYZ.c_str());
    reader->SetQFileName(o.Plot3DQ.c_str());
    reader->AutoDetectFormatOn();
    reader->SetScalarFunctionNumber(o.Plot3DFunction);
    reader->Update();
    vtkDataSet* block = vtkDataSet::SafeDownCast(reader->GetOutput()->GetBlock(0));
    if (!block)
    {
      return nullptr;
    }
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(block);
    tets->Update();
    grid = tets->GetOutput();
  }
  else if (!o.Input.empty())
  {
    const bool xml = o.Input.size() > 4 && o.Input.substr(o.Input.size() - 4) == ".vtu";
    if (xml)
    {
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName(o.Input.c_str());
      reader->Update();
      grid = reader->GetOutput();
    }
    else
    {
      vtkNew<vtkUnstructuredGridReader> reader;
      reader->SetFileName(o.Input.c_str());
      reader->Update();
      grid = reader->GetOutput();
    }
    // Tetrahedralize whatever cells it has (the stock mappers need it too).
    vtkNew<vtkDataSetTriangleFilter> tets;
    tets->SetInputData(grid);
    tets->Update();
    grid = tets->GetOutput();
  }
  else
  {
    grid = DefaultMesh();
  }
  if (grid && !o.Array.empty())
  {
    grid->GetPointData()->SetActiveScalars(o.Array.c_str());
  }
  if (grid && !grid->GetPointData()->GetScalars() && grid->GetPointData()->GetNumberOfArrays() > 0)
  {
    grid->GetPointData()->SetActiveScalars(grid->GetPointData()->GetArrayName(0));
  }
  return grid;
}

vtkSmartPointer<vtkVolumeProperty> MakeProperty(const double range[2], double unitDistance)
{
  const double lo = range[0], hi = range[1], span = hi - lo;
  // Every opacity node is also a colour node: VTK's
  // vtkUnstructuredGridLinearRayIntegrator (the ray-cast and ZSweep mappers'
  // exact integrator) splits segments at the colour nodes but, reading VTK
  // 9.2's source, only at the first opacity node, so it is exact only then.
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.05, 0.1, 0.9);
  color->AddRGBPoint(lo + 0.25 * span, 0.075, 0.5, 0.6);
  color->AddRGBPoint(lo + 0.5 * span, 0.1, 0.9, 0.3);
  color->AddRGBPoint(hi, 0.95, 0.3, 0.05);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(lo + 0.25 * span, 0.05);
  opacity->AddPoint(hi, 0.6);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->ShadeOff();
  property->SetInterpolationTypeToLinear();
  return property;
}

struct MapperRun
{
  std::string Name;
  std::vector<double> FrameSeconds;
  std::vector<double> Sort, Draw, Flush;
  std::vector<float> FirstImage;
  double Median(std::vector<double> v) const
  {
    if (v.empty())
    {
      return 0.0;
    }
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
};

std::vector<float> ReadRGBA(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  vtkNew<vtkFloatArray> data;
  window->GetRGBAPixelData(0, 0, size[0] - 1, size[1] - 1, 0, data);
  return std::vector<float>(data->GetPointer(0), data->GetPointer(0) + 4 * size[0] * size[1]);
}

}

int main(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--input")
      o.Input = next();
    else if (a == "--plot3d")
    {
      o.Plot3DXYZ = next();
      o.Plot3DQ = next();
      if (i + 1 < argc && argv[i + 1][0] != '-')
        o.Plot3DFunction = std::atoi(next().c_str());
    }
    else if (a == "--array")
      o.Array = next();
    else if (a == "--frames")
      o.Frames = std::max(1, std::atoi(next().c_str()));
    else if (a == "--size")
    {
      o.Width = std::max(1, std::atoi(next().c_str()));
      o.Height = std::max(1, std::atoi(next().c_str()));
    }
    else if (a == "--k")
      o.K = std::atoi(next().c_str());
    else if (a == "--output")
      o.Output = next();
    else
    {
      Usage();
      return a == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }

  vtkSmartPointer<vtkUnstructuredGrid> grid = LoadMesh(o);
  if (!grid || grid->GetNumberOfCells() == 0 || !grid->GetPointData()->GetScalars())
  {
    std::cerr << "havs_demo: could not load a mesh with point scalars." << std::endl;
    return EXIT_FAILURE;
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  double bounds[6];
  grid->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  auto property = MakeProperty(range, diagonal / 10.0);

  vtkNew<vtkHAVSVolumeMapper> havs;
  havs->SetKBufferSize(o.K);
  havs->MeasureStageTimesOn();
  vtkNew<vtkProjectedTetrahedraMapper> pt;
  vtkNew<vtkUnstructuredGridVolumeZSweepMapper> zsweep;
  zsweep->SetImageSampleDistance(1.0);
  zsweep->AutoAdjustSampleDistancesOff();
  zsweep->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());
  vtkNew<vtkUnstructuredGridVolumeRayCastMapper> raycast;
  raycast->SetImageSampleDistance(1.0);
  raycast->AutoAdjustSampleDistancesOff();
  raycast->SetRayIntegrator(vtkNew<vtkUnstructuredGridLinearRayIntegrator>());

  std::vector<std::pair<std::string, vtkUnstructuredGridVolumeMapper*>> mappers = {
    { "HAVS", havs }, { "ProjectedTetrahedra", pt }, { "ZSweep", zsweep }, { "RayCast", raycast }
  };

  std::string backend;
  std::vector<MapperRun> runs;
  vtkNew<vtkCamera> firstCamera; // the camera of every mapper's first frame
  for (auto& entry : mappers)
  {
    vtkSmartPointer<vtkRenderWindow> window;
    window.TakeReference(vtkHAVSRenderWindowFactory::CreateRenderWindow());
    if (!window)
    {
      return EXIT_FAILURE;
    }
    backend = vtkHAVSRenderWindowFactory::GetBackendName(window);
    window->SetSize(o.Width, o.Height);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0, 0, 0);
    window->AddRenderer(renderer);
    entry.second->SetInputData(grid);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(entry.second);
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    renderer->ResetCamera();
    renderer->GetActiveCamera()->Elevation(20.0);
    renderer->GetActiveCamera()->OrthogonalizeViewUp();
    renderer->ResetCameraClippingRange();

    MapperRun run;
    run.Name = entry.first;
    window->Render(); // first frame: builds faces, tables, shaders (not timed)
    run.FirstImage = ReadRGBA(window);
    firstCamera->DeepCopy(renderer->GetActiveCamera());
    for (int f = 0; f < o.Frames; ++f)
    {
      renderer->GetActiveCamera()->Azimuth(360.0 / o.Frames);
      renderer->ResetCameraClippingRange();
      const double start = vtkTimerLog::GetUniversalTime();
      window->Render();
      window->WaitForCompletion();
      run.FrameSeconds.push_back(vtkTimerLog::GetUniversalTime() - start);
      if (entry.second == havs.Get())
      {
        run.Sort.push_back(havs->GetLastFrameStatistics()->GetSortSeconds());
        run.Draw.push_back(havs->GetLastFrameStatistics()->GetDrawSeconds());
        run.Flush.push_back(havs->GetLastFrameStatistics()->GetFlushSeconds());
      }
    }
    runs.push_back(run);
    std::cerr << "havs_demo: " << run.Name << " done" << std::endl;
  }

  // The exact image of the first frame.
  vtkNew<vtkHAVSReferenceRenderer> reference;
  reference->SetInputData(grid);
  reference->SetProperty(property);
  reference->SetCamera(firstCamera);
  reference->SetSize(o.Width, o.Height);
  const double referenceStart = vtkTimerLog::GetUniversalTime();
  if (!reference->Render())
  {
    return EXIT_FAILURE;
  }
  const double referenceSeconds = vtkTimerLog::GetUniversalTime() - referenceStart;
  const vtkIdType pixels = static_cast<vtkIdType>(o.Width) * o.Height;
  vtkNew<vtkFloatArray> exactColour;
  exactColour->SetNumberOfComponents(4);
  exactColour->SetNumberOfTuples(pixels);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      exactColour->SetComponent(p, c, reference->GetImage()->GetComponent(p, c));
    }
    exactColour->SetComponent(p, 3, 0.0);
  }
  vtkNew<vtkHAVSImageMetrics> metrics;
  auto errorOf = [&](const std::vector<float>& image) {
    vtkNew<vtkFloatArray> seen;
    seen->SetNumberOfComponents(4);
    seen->SetNumberOfTuples(pixels);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      for (int c = 0; c < 3; ++c)
      {
        seen->SetComponent(p, c, image[4 * p + c]);
      }
      seen->SetComponent(p, 3, 0.0);
    }
    metrics->Compare(seen, exactColour);
    return std::make_pair(metrics->GetRMSE(), metrics->GetMaxAbsError());
  };
  const vtkIdType tets = grid->GetNumberOfCells();
  std::printf("\nvtkHAVS demo: %lld tets, %lld faces (%lld boundary), %dx%d, %d frames, window %s, "
              "SMP backend %s\n",
    static_cast<long long>(tets), static_cast<long long>(havs->GetNumberOfFaces()),
    static_cast<long long>(havs->GetNumberOfBoundaryFaces()), o.Width, o.Height, o.Frames,
    backend.c_str(), vtkSMPTools::GetBackend());
  std::printf("HAVS: k-buffer path %s, k = %d\n", havs->GetActiveKBufferPathName(),
    havs->GetActiveKBufferSize());
  std::printf("Stock mappers: ZSweep and RayCast with ImageSampleDistance 1, "
              "AutoAdjustSampleDistances off, vtkUnstructuredGridLinearRayIntegrator.\n\n");
  std::printf("Error: the first frame's colour against the exact reference (%.1f s to compute).\n\n",
    referenceSeconds);
  std::printf("| mapper | median ms/frame | sort ms | draw ms | flush ms | Mtets/s | RMSE | max error |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const MapperRun& r : runs)
  {
    const double ms = 1000.0 * r.Median(r.FrameSeconds);
    auto stage = [&](const std::vector<double>& v) {
      return v.empty() ? std::string("-") : std::to_string(1000.0 * r.Median(v)).substr(0, 7);
    };
    const auto error = errorOf(r.FirstImage);
    std::printf("| %s | %.1f | %s | %s | %s | %.3f | %.4f | %.4f |\n", r.Name.c_str(), ms,
      stage(r.Sort).c_str(), stage(r.Draw).c_str(), stage(r.Flush).c_str(),
      ms > 0 ? tets / (ms * 1000.0) : 0.0, error.first, error.second);
  }

  // Side by side: HAVS | PT | ZSweep | RayCast.
  vtkNew<vtkImageData> strip;
  strip->SetDimensions(o.Width * static_cast<int>(runs.size()), o.Height, 1);
  strip->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(strip->GetScalarPointer());
  for (size_t m = 0; m < runs.size(); ++m)
  {
    for (int y = 0; y < o.Height; ++y)
    {
      for (int x = 0; x < o.Width; ++x)
      {
        const float* p = &runs[m].FirstImage[4 * (y * o.Width + x)];
        unsigned char* q = out + 3 * (y * o.Width * runs.size() + m * o.Width + x);
        for (int c = 0; c < 3; ++c)
        {
          q[c] = static_cast<unsigned char>(std::min(std::max(p[c], 0.0f), 1.0f) * 255.0f + 0.5f);
        }
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(strip);
  writer->SetFileName(o.Output.c_str());
  writer->Write();
  std::printf("\nImages (HAVS | ProjectedTetrahedra | ZSweep | RayCast): %s\n", o.Output.c_str());
  return EXIT_SUCCESS;
}
