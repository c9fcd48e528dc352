/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSIntermixPass.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSIntermixPass.h"

#include "vtkHAVSMapperBase.h"
#include "vtkHAVSTranslucentLayers.h"

#include "vtkObjectFactory.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumetricPass.h"

VTK_ABI_NAMESPACE_BEGIN

namespace
{
/// The volumetric step: the layers composited first where no volume takes
/// them, then VTK's volumetric pass, then the layers nobody took.
class vtkHAVSIntermixVolumes : public vtkRenderPass
{
public:
  static vtkHAVSIntermixVolumes* New();
  vtkTypeMacro(vtkHAVSIntermixVolumes, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    vtkRenderer* renderer = s->GetRenderer();
    if (this->Layers->GetNumberOfLayers() > 0 &&
      !vtkHAVSIntermixPass::HasIntermixingVolume(renderer))
    {
      this->Layers->CompositeLayers(renderer);
    }
    this->Volumes->Render(s);
    this->NumberOfRenderedProps = this->Volumes->GetNumberOfRenderedProps();
    this->Layers->FinishFrame(renderer);
  }
  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Volumes->ReleaseGraphicsResources(window);
  }

  vtkHAVSTranslucentLayers* Layers = nullptr; // the pass's own, not owned
  vtkNew<vtkVolumetricPass> Volumes;

protected:
  vtkHAVSIntermixVolumes() = default;
  ~vtkHAVSIntermixVolumes() override = default;
};
vtkStandardNewMacro(vtkHAVSIntermixVolumes);
}

vtkStandardNewMacro(vtkHAVSIntermixPass);

//------------------------------------------------------------------------------
vtkHAVSIntermixPass::vtkHAVSIntermixPass()
{
  vtkNew<vtkHAVSIntermixVolumes> volumes;
  volumes->Layers = this->Layers;
  this->SetTranslucentPass(this->Layers);
  this->SetVolumetricPass(volumes);
}

vtkHAVSIntermixPass::~vtkHAVSIntermixPass() = default;

//------------------------------------------------------------------------------
bool vtkHAVSIntermixPass::HasIntermixingVolume(vtkRenderer* renderer, bool intermixing)
{
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    auto* mapper = volume ? vtkHAVSMapperBase::SafeDownCast(volume->GetMapper()) : nullptr;
    if (mapper && volume->GetVisibility() && (mapper->CanIntermix() || !intermixing))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkHAVSIntermixPass::HasTranslucentGeometry(const vtkRenderState* s)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (prop->GetVisibility() && !vtkVolume::SafeDownCast(prop) &&
      prop->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkHAVSIntermixPass::RenderSteps(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  for (vtkRenderPass* step : { this->LightsPass, this->OpaquePass, this->TranslucentPass,
         this->VolumetricPass, this->OverlayPass })
  {
    if (step)
    {
      step->Render(s);
      this->NumberOfRenderedProps += step->GetNumberOfRenderedProps();
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSIntermixPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layers:\n";
  this->Layers->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
