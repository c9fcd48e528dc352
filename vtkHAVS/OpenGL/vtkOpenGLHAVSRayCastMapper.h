/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSRayCastMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkOpenGLHAVSRayCastMapper
 * @brief   OpenGL layer of vtkHAVSRayCastMapper (its object-factory override).
 *
 * Per mesh: the points (vertex buffer), the boundary faces (index buffer) and
 * the tetrahedron behind each (storage buffer 5), the cells' planes and
 * fields (storage buffer 4) and their neighbours (storage buffer 6): the
 * layout of vtkHAVSRayCastMesh. Per frame, per pixel: the ray's state (the
 * eye distance it has reached, its opacity) and the entry the peeling found
 * (key and cell), in images. Each depth-peeling pass draws the front-facing
 * boundary faces twice (the nearest entry beyond each ray's reach, then its
 * cell) and then one full-viewport ray-casting pass that walks the rays from
 * those cells (one instance per screen tile, drawn only where the pass
 * found entries; storage buffer 8 holds each tile's last pass), blending
 * under the float result (vtkHAVSGLFrameTargets, which
 * also captures the opaque depth and composites over VTK's framebuffer).
 * Passes repeat until one starts no ray (a counter read back per pass).
 * With the camera inside the mesh the first pass also draws the near plane's
 * section (both facings), whose cells the rays start in.
 * Needs OpenGL 4.3 (storage buffers, image load/store).
 */
#ifndef vtkOpenGLHAVSRayCastMapper_h
#define vtkOpenGLHAVSRayCastMapper_h

#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkHAVSRayCastMapper.h"
#include "vtkNew.h" // For vtkNew

#include <vector> // For std::vector

class vtkHAVSGLFrameTargets;
class vtkHAVSGLTable;
class vtkOpenGLRenderWindow;

class VTKHAVSOPENGL_EXPORT vtkOpenGLHAVSRayCastMapper : public vtkHAVSRayCastMapper
{
public:
  static vtkOpenGLHAVSRayCastMapper* New();
  vtkTypeMacro(vtkOpenGLHAVSRayCastMapper, vtkHAVSRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkOpenGLHAVSRayCastMapper();
  ~vtkOpenGLHAVSRayCastMapper() override;

  bool DrawRays(vtkRenderer* renderer, const RayFrame& frame, RayCounts* counts) override;
  const std::vector<float>* GetKeptResult(int size[2]) override;

private:
  vtkOpenGLHAVSRayCastMapper(const vtkOpenGLHAVSRayCastMapper&) = delete;
  void operator=(const vtkOpenGLHAVSRayCastMapper&) = delete;

  void PrepareWindow(vtkOpenGLRenderWindow* window);
  void OnWindowDeleted(vtkObject* window, unsigned long, void*);
  void Upload(const RayFrame& frame);
  /// The near plane's section (triangles and their cells); returns its triangle count.
  int UploadSection(const RayFrame& frame);
  void ResizeImages(int width, int height);
  void ReleaseImages();

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;
  vtkNew<vtkHAVSGLTable> GLTable;
  vtkNew<vtkHAVSGLFrameTargets> Targets;
  unsigned int VertexArray = 0;
  unsigned int Buffers[8] = {}; // points, faces, face cells, cells, neighbours, counts, tiles,
                                // the tiles the next peel draws
  unsigned int TileArray = 0;   // (no attributes: the tiles' corners come from their ids)
  unsigned int Images[3] = { 0, 0, 0 }; // entry key, entry cell, ray state
  int ImageSize[2] = { 0, 0 };
  // The peeling's framebuffer: a stencil only (the tiles a pass peels).
  unsigned int PeelFramebuffer = 0;
  unsigned int PeelStencil = 0;
  unsigned int SectionArray = 0;
  unsigned int SectionBuffers[2] = { 0, 0 }; // points, cells
  int SectionTriangles = 0;
  vtkMTimeType UploadedSection = 0;
  int BoundaryFaces = 0;
  int Tetrahedra = 0;
  vtkMTimeType UploadedMesh = 0;
  vtkMTimeType UploadedTable = 0;
};

#endif
