/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTranslucentLayers.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSTranslucentLayers
 * @brief   The translucent pass of vtkHAVSIntermixPass: the translucent actors
 *          peeled into depth-ordered layers that a HAVS volume composites
 *          within itself.
 *
 * Render() draws the renderer's translucent polygonal geometry (VTK's
 * vtkTranslucentPass, each actor lit and shaded by its own mapper) once per
 * layer into a float colour texture and a depth texture of the viewport's
 * size: layer i holds, at each pixel, the nearest fragment behind layer
 * i - 1 and in front of the opaque geometry (depth peeling: the fragment
 * shader of VTK's polydata mapper discards the others, through this render
 * pass's shader replacements). It stops at the first empty layer or at
 * MaximumNumberOfLayers (the fragments beyond it are left out, warned once).
 * Nothing is drawn into the window: the layers are published on the
 * renderer's information (LAYERS()) for the volumes' mappers.
 *
 * A HAVS mapper that intermixes (vtkHAVSMapperBase::CanIntermix) takes them
 * (Take()) and composites each layer at its depth between the volume's
 * pieces. Layers nobody took are composited by CompositeLayers(), back to
 * front over the window: before the volumes when no volume of the renderer
 * can take them (VTK's own order, the translucent scene under the volumes),
 * after them otherwise (a frame that drew nothing).
 *
 * Each layer's colour is the fragment shader's output as VTK's mapper lit
 * it: RGB not premultiplied, and its opacity. Fragments within 1e-7 in
 * window depth of the previous layer are taken for the same surface (drawn
 * twice with slightly different depth), as VTK's depth peeling does.
 */
#ifndef vtkHAVSTranslucentLayers_h
#define vtkHAVSTranslucentLayers_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN
#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkNew.h"              // For vtkNew
#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkFloatArray;
class vtkHAVSGLFrameTargets;
class vtkInformationObjectBaseKey;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkTranslucentPass;

class VTKHAVSOPENGL_EXPORT vtkHAVSTranslucentLayers : public vtkOpenGLRenderPass
{
public:
  static vtkHAVSTranslucentLayers* New();
  vtkTypeMacro(vtkHAVSTranslucentLayers, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Peels the translucent actors of `s` into layers (nothing is drawn into the window).
  void Render(const vtkRenderState* s) override;

  ///@{
  /// The most layers peeled (8 by default, 1 to 64).
  vtkSetClampMacro(MaximumNumberOfLayers, int, 1, 64);
  vtkGetMacro(MaximumNumberOfLayers, int);
  ///@}

  /// The layers of the last Render() (0: no translucent fragment).
  vtkGetMacro(NumberOfLayers, int);
  /// Whether the last Render() filled every layer (fragments beyond may have been left out).
  vtkGetMacro(Truncated, bool);
  /// Whether a volume took the layers of this frame.
  vtkGetMacro(Taken, bool);
  /// The viewport's size the layers have.
  const int* GetSize() const { return this->Size; }

  /// The layers `renderer` published this frame (nullptr: none).
  static vtkHAVSTranslucentLayers* GetLayersOf(vtkRenderer* renderer);
  /// Takes the layers for one volume (false: none, or already taken).
  bool Take();
  /// Gives them back (the volume drew nothing).
  void GiveBack() { this->Taken = false; }

  ///@{
  /// Layer i's depth texture (window depth, 1 where it has no fragment) and
  /// its colour texture (RGBA32F: colour, opacity; zero where none).
  vtkTextureObject* GetDepthTexture(int i);
  vtkTextureObject* GetColorTexture(int i);
  ///@}

  /**
   * Reads layer i back (the renderer's window current): `depth` one value a
   * pixel, `rgba` four (colour, opacity), bottom row first. False when there
   * is no such layer.
   */
  bool ReadLayer(int i, vtkFloatArray* depth, vtkFloatArray* rgba);

  /**
   * Composites the layers back to front over the window at the renderer's
   * viewport (premultiplied by their opacity), the translucent scene as a
   * whole; marks them taken.
   */
  void CompositeLayers(vtkRenderer* renderer);

  /**
   * After the volumes: layers nobody took are composited over the window,
   * and the renderer's information no longer carries them.
   */
  void FinishFrame(vtkRenderer* renderer);

  /// The key on the renderer's information that carries the frame's layers.
  static vtkInformationObjectBaseKey* LAYERS();

  ///@{
  /// vtkOpenGLRenderPass: the peeling test in VTK's polydata fragment shader.
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkHAVSTranslucentLayers();
  ~vtkHAVSTranslucentLayers() override;

private:
  vtkHAVSTranslucentLayers(const vtkHAVSTranslucentLayers&) = delete;
  void operator=(const vtkHAVSTranslucentLayers&) = delete;

  /// The textures of `count` layers at this size.
  void Allocate(vtkOpenGLRenderWindow* window, int count, int width, int height);
  /// The window is going: its GL objects are released while its context lives.
  void OnWindowDeleted(vtkObject* window, unsigned long, void*);

  struct Layer
  {
    vtkSmartPointer<vtkTextureObject> Depth;
    vtkSmartPointer<vtkTextureObject> Color;
  };
  int MaximumNumberOfLayers = 8;
  int NumberOfLayers = 0;
  bool Truncated = false;
  bool WarnedTruncated = false;
  bool Taken = false;
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  int Peeling = 0; ///< the layer being peeled
  std::vector<Layer> Layers;
  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;
  vtkNew<vtkHAVSGLFrameTargets> Opaque; ///< the opaque depth (and the full-viewport triangle)
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTranslucentPass> Translucent;
};

VTK_ABI_NAMESPACE_END
#endif
