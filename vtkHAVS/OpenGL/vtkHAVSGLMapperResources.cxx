/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMapperResources.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSGLMapperResources.h"

#include "vtkHAVSGLCapabilities.h"
#include "vtkHAVSGLFrameTargets.h"
#include "vtkHAVSGLTable.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSGLMapperResources);

//------------------------------------------------------------------------------
vtkHAVSGLMapperResources::vtkHAVSGLMapperResources() = default;

vtkHAVSGLMapperResources::~vtkHAVSGLMapperResources()
{
  this->Release(nullptr);
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkHAVSGLMapperResources::Prepare(
  vtkRenderer* renderer, vtkObject* mapper, const char* mapperName, const char* needs)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorWithObjectMacro(mapper, << mapperName << " needs an OpenGL render window.");
    return nullptr;
  }
  if (this->Window != window)
  {
    this->Release(this->Window);
    this->Window = window;
    this->WindowDeleteObserver = window->AddObserver(
      vtkCommand::DeleteEvent, this, &vtkHAVSGLMapperResources::OnWindowDeleted);
    this->Table->SetContext(window);
    this->Targets->SetContext(window);
  }
  window->MakeCurrent();
  if (!vtkHAVSGLCapabilities::HasVersion(4, 3))
  {
    vtkErrorWithObjectMacro(mapper, << mapperName << " needs OpenGL 4.3 (" << needs << ").");
    return nullptr;
  }
  return window;
}

//------------------------------------------------------------------------------
void vtkHAVSGLMapperResources::OnWindowDeleted(vtkObject* window, unsigned long, void*)
{
  this->Release(vtkWindow::SafeDownCast(window));
}

void vtkHAVSGLMapperResources::Release(vtkWindow* window)
{
  if (!this->Window || (window && window != this->Window))
  {
    return;
  }
  vtkOpenGLRenderWindow* home = this->Window;
  home->MakeCurrent();
  if (this->ReleaseOwn)
  {
    this->ReleaseOwn(home);
  }
  this->Table->ReleaseGraphicsResources(home);
  this->Targets->ReleaseGraphicsResources(home);
  home->RemoveObserver(this->WindowDeleteObserver);
  this->Window = nullptr;
}

//------------------------------------------------------------------------------
void vtkHAVSGLMapperResources::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Window: " << this->Window << "\n";
  this->Table->PrintSelf(os, indent.GetNextIndent());
  this->Targets->PrintSelf(os, indent.GetNextIndent());
}

VTK_ABI_NAMESPACE_END
