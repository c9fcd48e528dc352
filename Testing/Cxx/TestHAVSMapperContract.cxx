/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSMapperContract.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// What every vtkHAVS mapper owes VTK and its users (issue 42), checked for
// the three mappers through vtkHAVSMapperBase's interface alone, each check
// with a control that must fail it:
// 1. VolumeMapperRenderStartEvent and EndEvent, once each per frame, in order
//    (control: a mapper that forwards Render to a HAVS mapper without them);
// 2. TimeToDraw set to the frame's time, which vtkVolume adds into its
//    estimated render time (control: the same forwarding mapper);
// 3. the render window's abort flag checked during the frame (an
//    AbortCheckEvent between the mapper's start and end events) and an
//    aborted frame drawing nothing: the volume's pixels stay background
//    (control: the same frame not aborted draws them);
// 4. the shared settings reach each mapper's mesh: HigherOrderSubdivision
//    refines a quadratic tetrahedron, VectorMode takes the magnitude
//    (control: the setting given to another mapper than the one drawn);
// 5. a mesh shared by two mappers (SetMesh): the second mapper prepares
//    nothing (GetLastMeshUpdate() == MeshShared), follows a new time step,
//    and draws the same image as with a mesh of its own (control: the
//    statistic of a mapper with its own mesh says MeshBuilt);
// 6. the volume's shader property: a fragment custom uniform, a declaration
//    at //VTK::Base::Dec and exit code at //VTK::Base::Exit halve the volume's
//    colour in every mapper (control: the uniform at 1 does not), and a
//    replacement of a tag the mappers lack (//VTK::Shading::Impl) gets
//    exactly one warning naming it over two frames and changes nothing
//    (control: a replacement of an honoured tag gets none);
// 7. the memory ledger, and the host copies freed after an upload, made
//    again after ReleaseGraphicsResources (the same image);
// 8. a mesh larger than LargestGPUBuffer allows: not drawn, one error; drawn
//    once the limit allows it (control: the limit at exactly the need);
// 9. a transfer-function edit redraws at once and exactly: after an opacity
//    node moved (the table rebuilt and uploaded into the same texture) the
//    float result equals that of a new mapper drawing the edited property
//    (control: the image before the edit differs), and the frame's table
//    time is its own (GetLastTableSeconds: positive in the edit's frame).
#include "havsTestChecks.h"
#include "havsTestImages.h"
#include "havsTestMessages.h"
#include "havsTestScenes.h"

#include "vtkHAVSCellGeometry.h"
#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSDataSets.h"
#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSRayCastMapper.h"
#include "vtkHAVSVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkSmartPointer.h"
#include "vtkUniforms.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using havstest::Check;

/// The control: a mapper that draws with a HAVS mapper inside but forgets
/// the contract (no events, no TimeToDraw, no abort check of its own).
class ForgetfulMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static ForgetfulMapper* New();
  vtkTypeMacro(ForgetfulMapper, vtkUnstructuredGridVolumeMapper);
  void Render(vtkRenderer* renderer, vtkVolume* volume) override
  {
    this->Inner->SetInputDataObject(this->GetDataObjectInput());
    this->Inner->Render(renderer, volume);
  }
  vtkNew<vtkHAVSRayCastMapper> Inner;

protected:
  ForgetfulMapper() = default;
};
vtkStandardNewMacro(ForgetfulMapper);

using MakeMapper = std::function<vtkSmartPointer<vtkUnstructuredGridVolumeMapper>()>;
struct Candidate
{
  std::string Name;
  MakeMapper Make;
  bool Control;
};

vtkSmartPointer<vtkUnstructuredGridVolumeMapper> Upcast(vtkUnstructuredGridVolumeMapper* m)
{
  return vtkSmartPointer<vtkUnstructuredGridVolumeMapper>::Take(m);
}

/// A new mapper of the same class as `like`, with its defaults.
vtkSmartPointer<vtkHAVSMapperBase> Another(vtkHAVSMapperBase* like)
{
  return vtkSmartPointer<vtkHAVSMapperBase>::Take(like->NewInstance());
}

/// Volume pixels: where the window differs from the background by more than 2/255.
int VolumePixels(const std::vector<float>& rgba)
{
  int n = 0;
  for (size_t i = 0; i + 3 < rgba.size(); i += 4)
  {
    if (std::abs(rgba[i]) + std::abs(rgba[i + 1]) + std::abs(rgba[i + 2]) > 2.0 / 255.0)
    {
      ++n;
    }
  }
  return n;
}

/// Checks 1-3 for one mapper; returns how many of them failed.
int CheckFrameContract(const Candidate& c, vtkUnstructuredGrid* grid, vtkVolumeProperty* property)
{
  const int before = havstest::Failures();
  vtkSmartPointer<vtkUnstructuredGridVolumeMapper> mapper = c.Make();
  havstest::VolumeScene scene = havstest::MakeScene(grid, mapper, property, 96, 96);
  vtkRenderWindow* window = scene.Window;

  // 1. The events, and the abort checks seen between them.
  struct Log
  {
    std::vector<std::string> Events;
    bool Inside = false;
    int AbortChecks = 0;
    bool AbortWanted = false;
    vtkRenderWindow* Window = nullptr;
  } log;
  log.Window = window;
  vtkNew<vtkCallbackCommand> onMapper;
  onMapper->SetClientData(&log);
  onMapper->SetCallback(
    [](vtkObject*, unsigned long event, void* data, void*)
    {
      auto* l = static_cast<Log*>(data);
      const bool start = event == vtkCommand::VolumeMapperRenderStartEvent;
      l->Events.push_back(start ? "start" : "end");
      l->Inside = start;
      if (start && l->AbortWanted)
      {
        l->Window->SetAbortRender(1);
      }
    });
  mapper->AddObserver(vtkCommand::VolumeMapperRenderStartEvent, onMapper);
  mapper->AddObserver(vtkCommand::VolumeMapperRenderEndEvent, onMapper);
  vtkNew<vtkCallbackCommand> onAbortCheck;
  onAbortCheck->SetClientData(&log);
  onAbortCheck->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*)
    {
      auto* l = static_cast<Log*>(data);
      l->AbortChecks += l->Inside ? 1 : 0;
    });
  window->AddObserver(vtkCommand::AbortCheckEvent, onAbortCheck);

  window->Render();
  const std::vector<float> drawn = havstest::ReadRGBA(window);
  Check(log.Events.size() == 2 && log.Events[0] == "start" && log.Events[1] == "end",
    c.Name + ": one VolumeMapperRenderStartEvent then one EndEvent per frame (seen " +
      std::to_string(log.Events.size()) + ")");
  Check(log.AbortChecks > 0,
    c.Name + ": the window's abort flag is checked during the frame (" +
      std::to_string(log.AbortChecks) + " checks)");

  // 2. TimeToDraw, and vtkVolume's estimate, which adds it in.
  const double seconds = mapper->GetTimeToDraw();
  Check(seconds > 0.0 && seconds < 60.0,
    c.Name + ": TimeToDraw is the frame's time (" + std::to_string(seconds) + " s)");
  Check(scene.Volume->GetEstimatedRenderTime() >= seconds && seconds > 0.0,
    c.Name + ": vtkVolume's estimated render time includes it (" +
      std::to_string(scene.Volume->GetEstimatedRenderTime()) + " s)");

  // 3. An aborted frame draws nothing (on a fresh window, so that no earlier
  // frame is left in it), and the same frame not aborted draws the volume.
  const int volumePixels = VolumePixels(drawn);
  Check(volumePixels > 500,
    c.Name + ": the frame draws the volume (" + std::to_string(volumePixels) + " pixels)");
  vtkSmartPointer<vtkUnstructuredGridVolumeMapper> fresh = c.Make();
  havstest::VolumeScene aborted = havstest::MakeScene(grid, fresh, property, 96, 96);
  log.Events.clear();
  log.AbortWanted = true;
  log.Window = aborted.Window;
  fresh->AddObserver(vtkCommand::VolumeMapperRenderStartEvent, onMapper);
  fresh->AddObserver(vtkCommand::VolumeMapperRenderEndEvent, onMapper);
  aborted.Window->Render();
  aborted.Window->SetAbortRender(0);
  // (The aborted window did not show its frame: show what the renderer drew.)
  aborted.Window->Frame();
  const int abortedPixels = VolumePixels(havstest::ReadRGBA(aborted.Window));
  Check(abortedPixels == 0,
    c.Name + ": an aborted frame draws nothing of the volume (" + std::to_string(abortedPixels) +
      " pixels)");
  if (auto* base = vtkHAVSMapperBase::SafeDownCast(fresh))
  {
    Check(base->GetLastFrameAborted(), c.Name + ": GetLastFrameAborted()");
  }
  return havstest::Failures() - before;
}

/// One quadratic tetrahedron with a 3-component point array "v" (the first
/// component x, the magnitude larger).
vtkSmartPointer<vtkUnstructuredGrid> MakeQuadraticTetra()
{
  const double corner[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const int edges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };
  vtkNew<vtkPoints> points;
  for (const auto& p : corner)
  {
    points->InsertNextPoint(p);
  }
  for (const auto& e : edges)
  {
    double m[3];
    for (int i = 0; i < 3; ++i)
    {
      m[i] = 0.5 * (corner[e[0]][i] + corner[e[1]][i]);
    }
    points->InsertNextPoint(m);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  vtkIdType ids[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9 };
  grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, ids);
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 10; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const double value[3] = { p[0], 2.0 + p[1], 2.0 + p[2] };
    v->InsertNextTuple(value);
  }
  grid->GetPointData()->SetScalars(v);
  return grid;
}

size_t TetsOf(vtkHAVSMapperBase* m)
{
  return m->GetMesh()->GetFaceSet()->GetTetrahedra().size() / 4;
}

/// Check 4: the shared settings reach `drawn`'s mesh when given to `set`.
bool SettingsReach(const std::string& name, vtkHAVSMapperBase* set, vtkHAVSMapperBase* drawn,
  vtkVolumeProperty* property, bool expect)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeQuadraticTetra();
  havstest::VolumeScene scene = havstest::MakeScene(grid, drawn, property, 64, 64);
  set->SetHigherOrderSubdivision(0);
  set->SetVectorMode(-1);
  scene.Window->Render();
  const size_t coarse = TetsOf(drawn);
  const double firstRange = drawn->GetMesh()->GetScalarRange()[1];
  set->SetHigherOrderSubdivision(2);
  set->SetVectorMode(0);
  scene.Window->Render();
  const size_t fine = TetsOf(drawn);
  const double magnitudeRange = drawn->GetMesh()->GetScalarRange()[1];
  const bool subdivided = fine > coarse;
  const bool magnitude = magnitudeRange > firstRange + 1.0;
  const std::string what = name + (expect ? "" : " (control: set on another mapper)") +
    ": HigherOrderSubdivision 2 refines the quadratic cell (" + std::to_string(coarse) + " -> " +
    std::to_string(fine) + " tets), VectorMode 0 takes the magnitude (range top " +
    std::to_string(firstRange) + " -> " + std::to_string(magnitudeRange) + ")";
  const bool reached = subdivided && magnitude;
  if (expect)
  {
    Check(reached, what);
  }
  else
  {
    Check(!subdivided && !magnitude, what + " must not change");
  }
  set->SetHigherOrderSubdivision(0);
  set->SetVectorMode(-1);
  return reached;
}
}

int TestHAVSMapperContract(int, char*[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = vtkHAVSDataSets::MakeBox(3, 3, 3, 1.0 / 3, 0.0, 1.0);
  vtkSmartPointer<vtkVolumeProperty> property = havstest::MakeRampPropertyFor(grid);

  const std::vector<Candidate> candidates = {
    { "vtkHAVSVolumeMapper", [] { return Upcast(vtkHAVSVolumeMapper::New()); }, false },
    { "vtkHAVSCellProjectionMapper", [] { return Upcast(vtkHAVSCellProjectionMapper::New()); },
      false },
    { "vtkHAVSRayCastMapper", [] { return Upcast(vtkHAVSRayCastMapper::New()); }, false },
    { "ForgetfulMapper (control)", [] { return Upcast(ForgetfulMapper::New()); }, true },
  };
  for (const Candidate& c : candidates)
  {
    std::cout << "--- " << c.Name
              << (c.Control ? ": must fail; its CHECK FAILED lines are expected" : "") << "\n";
    const int failed = CheckFrameContract(c, grid, property);
    if (c.Control)
    {
      // The control must fail the contract; its failures are expected.
      havstest::Failures() -= failed;
      Check(failed >= 3,
        "the control fails the events, TimeToDraw and abort checks (" + std::to_string(failed) +
          " failed)");
    }
  }

  // 4. The shared settings, through the base's interface.
  std::vector<vtkSmartPointer<vtkHAVSMapperBase>> mappers;
  mappers.emplace_back(vtkSmartPointer<vtkHAVSVolumeMapper>::New());
  mappers.emplace_back(vtkSmartPointer<vtkHAVSCellProjectionMapper>::New());
  mappers.emplace_back(vtkSmartPointer<vtkHAVSRayCastMapper>::New());
  for (size_t i = 0; i < mappers.size(); ++i)
  {
    vtkHAVSMapperBase* m = mappers[i];
    SettingsReach(m->GetClassName(), m, m, property, true);
  }
  {
    vtkNew<vtkHAVSRayCastMapper> other;
    vtkNew<vtkHAVSRayCastMapper> drawn;
    SettingsReach("vtkHAVSRayCastMapper", other, drawn, property, false);
  }

  // 5. One mesh for two mappers: the second prepares nothing, follows a new
  // time step, and draws what it draws with a mesh of its own.
  {
    vtkSmartPointer<vtkUnstructuredGrid> box = vtkHAVSDataSets::MakeBox(4, 4, 4, 0.25, 0.0, 1.0);
    vtkNew<vtkHAVSVolumeMapper> havs;
    vtkNew<vtkHAVSRayCastMapper> sharing;
    vtkNew<vtkHAVSRayCastMapper> own;
    sharing->SetMesh(havs->GetMesh());
    Check(sharing->GetMesh() == havs->GetMesh(), "SetMesh shares the mesh");
    havstest::VolumeScene a = havstest::MakeScene(box, havs, property, 96, 96);
    havstest::VolumeScene b = havstest::MakeScene(box, sharing, property, 96, 96);
    havstest::VolumeScene c = havstest::MakeScene(box, own, property, 96, 96);
    a.Window->Render();
    Check(havs->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshBuilt, "the first mapper builds it");
    b.Window->Render();
    c.Window->Render();
    Check(sharing->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshShared,
      std::string("the second mapper's mesh: ") +
        vtkHAVSMapperBase::GetMeshUpdateName(sharing->GetLastMeshUpdate()));
    Check(own->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshBuilt,
      "control: a mapper with its own mesh builds it");
    havstest::ImageDifference d =
      havstest::Compare(havstest::ReadRGBA(b.Window), havstest::ReadRGBA(c.Window));
    Check(d.Max == 0.0, "the shared mesh draws the same image (max " + std::to_string(d.Max) + ")");
    b.Window->Render();
    Check(
      sharing->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshUnchanged, "then unchanged for it");

    // A new time step: other values of the same array on the same mesh.
    vtkDataArray* s = box->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    {
      s->SetTuple1(i, 1.0 - s->GetTuple1(i));
    }
    s->Modified();
    a.Window->Render();
    b.Window->Render();
    c.Window->Render();
    Check(havs->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshScalarsMapped,
      std::string("a new time step maps the scalars: ") +
        vtkHAVSMapperBase::GetMeshUpdateName(havs->GetLastMeshUpdate()));
    Check(sharing->GetLastMeshUpdate() == vtkHAVSMapperBase::MeshShared,
      "the sharing mapper follows it without work");
    d = havstest::Compare(havstest::ReadRGBA(b.Window), havstest::ReadRGBA(c.Window));
    Check(d.Max == 0.0,
      "and draws the new time step as its own mesh does (max " + std::to_string(d.Max) + ")");
  }

  // 6. The volume's shader property, through the base: the honoured tags
  // applied in the composite (a custom uniform, a declaration, the exit code),
  // anything else said once and left out.
  for (size_t i = 0; i < mappers.size(); ++i)
  {
    const std::string name = mappers[i]->GetClassName();
    auto draw = [&](const std::function<void(vtkShaderProperty*)>& customize, int* warnings,
                  std::string* text)
    {
      vtkSmartPointer<vtkHAVSMapperBase> m = Another(mappers[i]);
      havstest::VolumeScene scene = havstest::MakeScene(grid, m, property, 64, 64);
      customize(scene.Volume->GetShaderProperty());
      havstest::Messages* messages = havstest::CountMessages(m);
      scene.Window->Render();
      scene.Window->Render();
      *warnings = messages->Warnings;
      *text = messages->Text;
      return havstest::ReadRGBA(scene.Window);
    };
    int warnings = 0;
    std::string text;
    const std::vector<float> plain = draw([](vtkShaderProperty*) {}, &warnings, &text);
    Check(warnings == 0 && VolumePixels(plain) > 100,
      name + ": without a shader property, no warning and a volume (" +
        std::to_string(VolumePixels(plain)) + " pixels)");
    // The largest difference, in the colour channels, between `image` and
    // `scale` times the plain image (on a black background the composite is
    // the volume's premultiplied colour).
    auto offScaled = [&](const std::vector<float>& image, double scale)
    {
      double worst = image.size() == plain.size() ? 0.0 : 1e30;
      for (size_t p = 0; p + 3 < plain.size() && p + 3 < image.size(); p += 4)
      {
        for (size_t c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(image[p + c] - scale * plain[p + c]));
        }
      }
      return worst;
    };
    for (double tint : { 0.5, 1.0 })
    {
      const std::vector<float> tinted = draw(
        [tint](vtkShaderProperty* sp)
        {
          sp->GetFragmentCustomUniforms()->SetUniformf("havsTestTint", static_cast<float>(tint));
          sp->AddFragmentShaderReplacement("//VTK::Base::Dec", true,
            "vec4 havsTestScale(vec4 c) { return c * havsTestTint; }", false);
          sp->AddFragmentShaderReplacement(
            "//VTK::Base::Exit", true, "g_fragColor = havsTestScale(g_fragColor);", false);
        },
        &warnings, &text);
      const double off = offScaled(tinted, 0.5);
      // Two 8-bit roundings: the plain image's and the tinted one's.
      const bool halved = off <= 1.5 / 255.0;
      Check(warnings == 0 && (tint == 0.5 ? halved : !halved),
        name +
          (tint == 0.5 ? ": a uniform, a declaration and exit code halve the volume's colour"
                       : ": control, the same with the uniform at 1: not halved") +
          " (max " + std::to_string(off * 255.0) + "/255 from half the plain image, " +
          std::to_string(warnings) + " warnings)");
    }
    {
      // Edits between frames of one mapper redraw at once: hooks added after a
      // plain frame apply, and cleared they are gone (the hooks and the composite
      // are read again only when the property changed).
      vtkSmartPointer<vtkHAVSMapperBase> m = Another(mappers[i]);
      havstest::VolumeScene scene = havstest::MakeScene(grid, m, property, 64, 64);
      scene.Window->Render();
      vtkShaderProperty* sp = scene.Volume->GetShaderProperty();
      sp->GetFragmentCustomUniforms()->SetUniformf("havsTestTint", 0.5f);
      sp->AddFragmentShaderReplacement(
        "//VTK::Base::Exit", true, "g_fragColor = g_fragColor * havsTestTint;", false);
      scene.Window->Render();
      const double halvedOff = offScaled(havstest::ReadRGBA(scene.Window), 0.5);
      sp->ClearAllFragmentShaderReplacements();
      sp->GetFragmentCustomUniforms()->RemoveAllUniforms();
      scene.Window->Render();
      const double plainOff = offScaled(havstest::ReadRGBA(scene.Window), 1.0);
      Check(halvedOff <= 1.5 / 255.0 && plainOff == 0.0,
        name + ": hooks added after a frame apply at the next (max " +
          std::to_string(halvedOff * 255.0) + "/255 from half), cleared they are gone (max " +
          std::to_string(plainOff * 255.0) + "/255 from plain)");
    }
    for (bool ignored : { true, false })
    {
      const std::vector<float> image = draw(
        [ignored](vtkShaderProperty* sp)
        {
          sp->AddFragmentShaderReplacement(
            ignored ? "//VTK::Shading::Impl" : "//VTK::Base::Dec", true, "// a user's line", false);
        },
        &warnings, &text);
      const bool said = warnings == 1 && text.find("//VTK::Shading::Impl") != std::string::npos;
      Check((ignored ? said : warnings == 0) && offScaled(image, 1.0) == 0.0,
        name +
          (ignored ? ": a tag it does not have (//VTK::Shading::Impl): one warning naming it"
                   : ": control, an honoured tag: no warning") +
          ", the image unchanged (" + std::to_string(warnings) + " warnings)");
    }
  }

  // 7. The memory ledger, and the host copies freed after an upload: a frame
  // after ReleaseGraphicsResources makes them again and draws the same image.
  for (size_t i = 0; i < mappers.size(); ++i)
  {
    const std::string name = mappers[i]->GetClassName();
    vtkSmartPointer<vtkHAVSMapperBase> m = Another(mappers[i]);
    havstest::VolumeScene scene = havstest::MakeScene(grid, m, property, 64, 64);
    scene.Window->Render();
    const std::vector<float> first = havstest::ReadRGBA(scene.Window);
    const size_t tets = static_cast<size_t>(grid->GetNumberOfCells());
    size_t meshBytes = 0, gpuBytes = 0, sum = 0;
    const std::vector<vtkHAVSMemory::Part> parts = m->GetMemoryParts();
    for (const vtkHAVSMemory::Part& part : parts)
    {
      sum += part.Bytes;
      meshBytes += part.Name.rfind("mesh", 0) == 0 ? part.Bytes : 0;
      gpuBytes += part.Name.rfind("GPU", 0) == 0 ? part.Bytes : 0;
    }
    Check(sum == m->GetMemoryBytes() && meshBytes >= 16 * tets && gpuBytes >= 16 * tets,
      name + ": the ledger holds the mesh (" + std::to_string(meshBytes / tets) +
        " B a tetrahedron) and the GPU buffers (" + std::to_string(gpuBytes / tets) + ")");
    m->ReleaseGraphicsResources(scene.Window);
    size_t released = 0;
    for (const vtkHAVSMemory::Part& part : m->GetMemoryParts())
    {
      released += part.Name.rfind("GPU", 0) == 0 ? part.Bytes : 0;
    }
    scene.Window->Render();
    const double off = havstest::Compare(havstest::ReadRGBA(scene.Window), first).Max;
    Check(released < gpuBytes && off == 0.0,
      name + ": after ReleaseGraphicsResources (GPU buffers " + std::to_string(gpuBytes) + " -> " +
        std::to_string(released) + " B) the next frame draws the same (max " +
        std::to_string(off * 255.0) + "/255)");
  }

  // 8. A mesh whose largest GPU buffer would be larger than LargestGPUBuffer:
  // not drawn, one error, no crash; the same mapper draws it once the limit
  // allows it (the same image as a mapper that never refused, max 0).
  // Control: the limit at exactly the need draws.
  for (size_t i = 0; i < mappers.size(); ++i)
  {
    const std::string name = mappers[i]->GetClassName();
    vtkSmartPointer<vtkHAVSMapperBase> plain = Another(mappers[i]);
    havstest::VolumeScene reference = havstest::MakeScene(grid, plain, property, 64, 64);
    reference.Window->Render();
    const std::vector<float> expected = havstest::ReadRGBA(reference.Window);
    const size_t need = plain->GetLargestGPUBufferNeed().Bytes;

    vtkSmartPointer<vtkHAVSMapperBase> m = Another(mappers[i]);
    havstest::Messages* messages = havstest::CountMessages(m);
    m->SetLargestGPUBuffer(static_cast<vtkIdType>(need) - 1);
    havstest::VolumeScene scene = havstest::MakeScene(grid, m, property, 64, 64);
    scene.Window->Render();
    const int refusedPixels = VolumePixels(havstest::ReadRGBA(scene.Window));
    scene.Window->Render();
    const int errors = messages->Errors;
    Check(need >= 12 * static_cast<size_t>(TetsOf(m)) && refusedPixels == 0 && errors == 1,
      name + ": a mesh needing " + std::to_string(need) + " bytes in one buffer, 1 over the " +
        "limit: nothing drawn (" + std::to_string(refusedPixels) + " volume pixels), " +
        std::to_string(errors) + " error over two frames");
    m->SetLargestGPUBuffer(static_cast<vtkIdType>(need));
    scene.Window->Render();
    const double off = havstest::Compare(havstest::ReadRGBA(scene.Window), expected).Max;
    // The ray caster's and the cell projection's cell records (80 bytes a
    // tetrahedron) then lie in 4 buffers (vtkHAVSGLCellRecords): the same
    // image as in one.
    const bool split = name.find("VolumeMapper") != std::string::npos ||
      need < vtkHAVSCellGeometry::RecordBytes * static_cast<size_t>(TetsOf(m));
    Check(off == 0.0 && messages->Errors == 1 && VolumePixels(expected) > 100 && split,
      name + ": the limit at the need: drawn as a mapper that never refused (max " +
        std::to_string(off * 255.0) + "/255)" +
        (name.find("VolumeMapper") != std::string::npos
            ? std::string()
            : std::string(split ? ", its cell records in several buffers"
                                : ", but its cell records fit one buffer: no split tested")));
  }
  // 9. A transfer-function edit redraws at once, as a new mapper would draw it.
  for (size_t i = 0; i < mappers.size(); ++i)
  {
    const std::string name = mappers[i]->GetClassName();
    vtkSmartPointer<vtkVolumeProperty> edited = vtkSmartPointer<vtkVolumeProperty>::New();
    edited->DeepCopy(property);
    vtkSmartPointer<vtkHAVSMapperBase> m = Another(mappers[i]);
    vtkSmartPointer<vtkHAVSMapperBase> other = Another(mappers[i]);
    m->KeepFloatResultOn();
    other->KeepFloatResultOn();
    havstest::VolumeScene scene = havstest::MakeScene(grid, m, edited, 64, 64);
    scene.Window->Render();
    scene.Window->Render();
    const std::vector<float> before = havstest::FloatResult(m);
    vtkPiecewiseFunction* opacity = edited->GetScalarOpacity();
    double node[4];
    opacity->GetNodeValue(opacity->GetSize() - 1, node);
    node[1] *= 0.5;
    opacity->SetNodeValue(opacity->GetSize() - 1, node);
    scene.Window->Render();
    const double tableSeconds = m->GetLastTableSeconds();
    const std::vector<float> after = havstest::FloatResult(m);
    havstest::VolumeScene second = havstest::MakeScene(grid, other, edited, 64, 64);
    second.Window->Render();
    const havstest::ImageDifference same = havstest::Compare(after, havstest::FloatResult(other));
    const havstest::ImageDifference changed = havstest::Compare(before, after);
    std::cout << name << ": edit against a new mapper max " << same.Max << ", against before "
              << changed.Max << ", table " << 1000.0 * tableSeconds << " ms\n";
    Check(!after.empty() && same.Max < 1e-6,
      name + ": an edit redraws as a new mapper draws the edited property (max " +
        std::to_string(same.Max) + ")");
    Check(changed.Max > 0.01,
      name + ": control, the image before the edit differs (max " + std::to_string(changed.Max) +
        ")");
    Check(tableSeconds > 0.0,
      name + ": the edit's frame rebuilt its table (" + std::to_string(1000.0 * tableSeconds) +
        " ms)");
  }

  return havstest::Result();
}
