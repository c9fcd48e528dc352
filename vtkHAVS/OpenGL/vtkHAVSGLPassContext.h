/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLPassContext.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLPassContext
 * @brief   What every GPU pass of one frame shares: resources, request, programs.
 *
 * Made by vtkOpenGLHAVSVolumeMapper for each frame and handed to the k-buffer
 * paths (vtkHAVSKBuffer) and the other passes: the window, the mesh, table
 * and targets on the GPU, the frame's request with its matrices as OpenGL
 * floats, and the programs of the face and full-viewport passes with the
 * uniforms they all read. vtkHAVSGLScopedPassState saves the GL state a pass
 * changes and sets what every pass needs.
 */
#ifndef vtkHAVSGLPassContext_h
#define vtkHAVSGLPassContext_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSFrameRequest.h" // For FrameRequest
#include "vtkHAVSShaders.h"      // For Features
#include "vtkOpenGLState.h"      // For the scoped state savers

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLFrameTargets;
class vtkHAVSGLMesh;
class vtkHAVSGLTable;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;

class vtkHAVSGLPassContext
{
public:
  vtkHAVSGLPassContext(vtkOpenGLRenderWindow* window, vtkHAVSGLMesh* mesh, vtkHAVSGLTable* table,
    vtkHAVSGLFrameTargets* targets, const vtkHAVSFrameRequest& request);

  vtkOpenGLRenderWindow* Window;
  vtkHAVSGLMesh* Mesh;
  vtkHAVSGLTable* Table;
  vtkHAVSGLFrameTargets* Targets;
  const vtkHAVSFrameRequest& Request;

  /// The image drawn (a reduced frame's is smaller than the viewport).
  int Width() const;
  int Height() const;
  /// The size per-pixel buffers are allocated at (the viewport's: reduced
  /// frames reuse them, drawing in their lower left corner).
  int AllocatedWidth() const;
  int AllocatedHeight() const;

  /// What the frame's k-buffer shaders compile in (counter, tagging, opaque cut).
  vtkHAVSShaders::Features ShaderFeatures() const;

  /// The face vertex shader with `fragmentShader`, common uniforms set; nullptr on failure.
  vtkShaderProgram* FaceProgram(const std::string& fragmentShader);
  /// The full-viewport vertex shader with `fragmentShader`, common uniforms set.
  vtkShaderProgram* QuadProgram(const std::string& fragmentShader);
  /// The mesh's faces (and sections) with `program`.
  void DrawFaces(vtkShaderProgram* program);
  /// A full-viewport triangle.
  void DrawFullViewport();

private:
  vtkShaderProgram* Program(const std::string& vertexShader, const std::string& fragmentShader);
  void SetCommonUniforms(vtkShaderProgram* program);

  float ModelToEyeRelative[16];
  float ModelToClip[16];
  float ClipToEyeRelative[16];
  float Direction[3];
};

/// Saves the GL state a vtkHAVS pass changes (restored when it goes out of
/// scope) and sets what every pass needs: no depth test, culling or scissor,
/// no depth writes.
struct vtkHAVSGLScopedPassState
{
  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglEnableDisable DepthTest;
  vtkOpenGLState::ScopedglEnableDisable Blend;
  vtkOpenGLState::ScopedglEnableDisable Cull;
  vtkOpenGLState::ScopedglEnableDisable Scissor;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;

  explicit vtkHAVSGLScopedPassState(vtkOpenGLState* state);
};

VTK_ABI_NAMESPACE_END
#endif
