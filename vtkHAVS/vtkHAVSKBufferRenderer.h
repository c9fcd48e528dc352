/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSKBufferRenderer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSKBufferRenderer
 * @brief   The OpenGL layer of vtkHAVSVolumeMapper: buffers, shaders, passes.
 *
 * Everything that touches OpenGL lives here; the mapper hands it plain arrays
 * (points, normalized scalars, sorted triangles, boundary flags, the
 * pre-integrated table) and per-frame matrices. One frame:
 *
 *   CaptureOpaqueDepth  copy the depth of VTK's framebuffer (opaque geometry)
 *   Clear               empty k-buffer
 *   Draw                the faces in sorted order through the k-buffer
 *   Resolve (flush)     remaining entries leave in depth order -> result
 *   Composite           result (premultiplied) over VTK's framebuffer
 *
 * Three k-buffer paths, chosen by what the context offers (or forced):
 * - FramebufferFetch: entries in colour attachments read with
 *   EXT_shader_framebuffer_fetch (coherent, ordered per primitive); k <= 14
 *   with 8 draw buffers.
 * - FragmentShaderInterlock: entries in a per-pixel storage buffer, the
 *   read-modify-write inside an ordered pixel interlock (ARB/NV); any k up to
 *   MaximumInterlockK.
 * - FragmentLists: every fragment appended to a per-pixel linked list; the
 *   resolve pass runs each list through a k-buffer as large as
 *   ListResolveCapacity, which sorts any list of up to that many fragments
 *   exactly, whatever order they came in. The result does not depend on k.
 */
#ifndef vtkHAVSKBufferRenderer_h
#define vtkHAVSKBufferRenderer_h

#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <memory>  // For std::unique_ptr
#include <string>  // For std::string
#include <vector>  // For std::vector

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkWindow;

class vtkHAVSKBufferRenderer : public vtkObject
{
public:
  static vtkHAVSKBufferRenderer* New();
  vtkTypeMacro(vtkHAVSKBufferRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Path
  {
    FramebufferFetch = 1,
    FragmentShaderInterlock = 2,
    FragmentLists = 3
  };
  static const char* GetPathName(int path);

  static constexpr int MaximumFetchK = 14;
  static constexpr int MaximumInterlockK = 64;
  static constexpr int ListResolveCapacity = 64;

  /**
   * Whether the context of `window` can run `path` (made current first).
   */
  static bool IsPathSupported(vtkOpenGLRenderWindow* window, int path);

  /**
   * The largest k the path holds.
   */
  static int GetMaximumK(int path);

  /// Per-frame inputs. Matrices are OpenGL column-major floats.
  struct FrameParameters
  {
    int Path = FramebufferFetch;
    int K = 2;
    int BlendMode = 0; // 0 composite, 1 maximum, 2 minimum intensity
    float MCRC[16];    // model -> eye-relative world
    float MCDC[16];    // model -> clip
    float DCRC[16];    // clip -> eye-relative world
    float DirectionOfProjection[3];
    bool Parallel = false;
    bool FlipFacing = false; // the volume matrix mirrors (negative determinant)
    float TerminationOpacity = 1.0f;
    bool MeasureStages = false;
    bool KeepResult = false;
    bool RasterBoundOnly = false; // benchmark aid: faces with a trivial shader, nothing else
    bool Composite = true;            // composite the result over the window (else keep it)
    bool CountOrderViolations = true; // read the order-violation counter back after the frame
    bool Tagging = true;          // boundary faces carry their entry/exit role
    float GapLength = 3.0e38f;    // segments longer than this contribute nothing (3e38: off)
    int PlaneCount = 0;           // clipping planes (and the near plane), eye-relative world:
    float PlanesRC[7][4];         // kept where dot(xyz, x) + w >= 0
  };

  /**
   * A cross-section of the mesh with plane PlaneIndex of FrameParameters:
   * triangles (3 points of 3 floats, model coordinates, and 3 normalized
   * scalars each) drawn as entries into the clipped volume before the faces
   * (Entering) or as exits after them.
   */
  struct Section
  {
    int PlaneIndex = 0;
    bool Entering = true;
    std::vector<float> PointsMC;
    std::vector<float> Scalars;
  };

  /// The sections of the next frames (uploaded at once; empty: none).
  void SetSections(const std::vector<Section>& sections);

  /**
   * Makes `window` the context of every resource. Returns true when the
   * resources are new there (first use, or moved from another window: the old
   * window's are released) and everything must be uploaded again.
   */
  bool PrepareWindow(vtkOpenGLRenderWindow* window);

  /// Uploads points (3 floats each, model coordinates) and normalized scalars.
  void SetGeometry(const std::vector<float>& pointsMC, const std::vector<float>& scalars);
  /// Uploads the faces in draw order (3 point ids each) and their boundary flags.
  void SetFaceOrder(const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& boundary);
  /// Uploads the pre-integrated table (RGBA, front fastest) and the 1D function.
  void SetTable(const float* table, int scalarResolution, int lengthResolution, double maxLength,
    const std::vector<float>& transferFunction1D);

  /**
   * Renders one frame into the current framebuffer of the renderer's window.
   * Returns false (with an error) when it cannot.
   */
  bool Render(vtkRenderer* renderer, const FrameParameters& parameters);

  /**
   * Composites the result of the last frame (rendered with Composite off)
   * over the renderer's framebuffer.
   */
  bool CompositeLastResult(vtkRenderer* renderer);

  void ReleaseGraphicsResources(vtkWindow* window);

  ///@{
  /// Stage times of the last frame in seconds (GPU work finished at each
  /// stage end only when FrameParameters::MeasureStages was set).
  double GetLastDrawSeconds() const { return this->LastDrawSeconds; }
  double GetLastFlushSeconds() const { return this->LastFlushSeconds; }
  double GetLastCompositeSeconds() const { return this->LastCompositeSeconds; }
  ///@}

  /**
   * The premultiplied float RGBA result of the last frame (viewport size,
   * bottom row first) when FrameParameters::KeepResult was set.
   */
  const std::vector<float>& GetLastResult() const { return this->LastResult; }
  int GetLastResultWidth() const { return this->LastSize[0]; }
  int GetLastResultHeight() const { return this->LastSize[1]; }

  /**
   * Fragments composited out of depth order in the last frame (nearer than
   * what their pixel had been integrated to, beyond float rounding); 0 when
   * not counted (FrameParameters::CountOrderViolations off, extremum modes).
   */
  std::uint64_t GetLastOrderViolations() const { return this->LastOrderViolations; }
  /// Where: x, y of the first (up to 16) violations, in viewport pixels.
  const std::vector<int>& GetLastViolationPixels() const { return this->LastViolationPixels; }

  /// Fragment-list path: fragments stored in the last frame.
  std::uint64_t GetLastFragmentCount() const { return this->LastFragmentCount; }

protected:
  vtkHAVSKBufferRenderer();
  ~vtkHAVSKBufferRenderer() override;

private:
  vtkHAVSKBufferRenderer(const vtkHAVSKBufferRenderer&) = delete;
  void operator=(const vtkHAVSKBufferRenderer&) = delete;

  /// Releases the resources when their window is deleted.
  void OnWindowDeleted(vtkObject* window, unsigned long event, void* data);

  struct Internals;
  std::unique_ptr<Internals> Internal;

  double LastDrawSeconds = 0.0;
  double LastFlushSeconds = 0.0;
  double LastCompositeSeconds = 0.0;
  std::vector<float> LastResult;
  int LastSize[2] = { 0, 0 };
  std::uint64_t LastFragmentCount = 0;
  std::uint64_t LastOrderViolations = 0;
  std::vector<int> LastViolationPixels;
};

#endif
