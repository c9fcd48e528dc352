/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSSurfacelessRenderWindow.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSSurfacelessRenderWindow.h"

#include "vtkHAVSOpenGL.h"
#include "vtkOpenGLState.h"

VTK_ABI_NAMESPACE_BEGIN

//------------------------------------------------------------------------------
void vtkHAVSSurfacelessRenderWindow::OpenGLInitContext()
{
#if defined(VTKHAVS_USES_GLEW)
  if (!this->Initialized)
  {
    this->ContextCreationTime.Modified();
    glewExperimental = GL_TRUE;
    const GLenum result = glewInit();
    // GLEW loads the GL entry points first, then fails in its GLX part when no
    // GLX display exists or no GLX context is current: that one error is
    // expected here.
    if (result != GLEW_OK && result != GLEW_ERROR_NO_GLX_DISPLAY)
    {
      vtkErrorMacro("GLEW could not be initialized on the "
        << this->GetContextName()
        << " context: " << reinterpret_cast<const char*>(glewGetErrorString(result)));
      return;
    }
    if (!GLEW_VERSION_3_2)
    {
      const GLubyte* version = glGetString(GL_VERSION);
      vtkErrorMacro("The " << this->GetContextName()
                           << " context does not provide OpenGL 3.2 to VTK (GL_VERSION '"
                           << (version ? reinterpret_cast<const char*>(version) : "") << "').");
      return;
    }
    this->GlewInitValid = true;
    this->Initialized = true;
    GLfloat lineWidthRange[2] = { 1.0f, 1.0f };
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, lineWidthRange);
    this->MaximumHardwareLineWidth = (glGetError() == GL_NO_ERROR) ? lineWidthRange[1] : 1.0f;
    return;
  }
#endif
  this->Superclass::OpenGLInitContext();
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHAVSSurfacelessRenderWindow::IsDirect()
{
  return 1;
}

//------------------------------------------------------------------------------
void vtkHAVSSurfacelessRenderWindow::Frame()
{
  // Nothing to present. Keep VTK's framebuffer bindings in sync.
  if (this->Initialized && this->IsCurrent())
  {
    this->GetState()->ResetFramebufferBindings();
  }
}

//------------------------------------------------------------------------------
int vtkHAVSSurfacelessRenderWindow::GetColorBufferSizes(int* rgba)
{
  GLint drawFramebuffer = 0;
  if (this->Initialized && this->IsCurrent())
  {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  }
  if (drawFramebuffer != 0)
  {
    return this->Superclass::GetColorBufferSizes(rgba);
  }
  if (!rgba)
  {
    return 0;
  }
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 8;
  return 32;
}

//------------------------------------------------------------------------------
void vtkHAVSSurfacelessRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << this->GetContextName() << "\n";
}

VTK_ABI_NAMESPACE_END
