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

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkHAVSRayCastMapper.h"
#include "vtkNew.h" // For vtkNew

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLMapperResources;
class vtkHAVSGLQueries;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;

class VTKHAVSOPENGL_EXPORT vtkOpenGLHAVSRayCastMapper : public vtkHAVSRayCastMapper
{
public:
  static vtkOpenGLHAVSRayCastMapper* New();
  vtkTypeMacro(vtkOpenGLHAVSRayCastMapper, vtkHAVSRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkOpenGLHAVSRayCastMapper();
  ~vtkOpenGLHAVSRayCastMapper() override;

  bool DrawRays(vtkRenderer* renderer, const RayFrame& frame, RayCounts* counts) override;

private:
  vtkOpenGLHAVSRayCastMapper(const vtkOpenGLHAVSRayCastMapper&) = delete;
  void operator=(const vtkOpenGLHAVSRayCastMapper&) = delete;

  /// The frame's three programs: the peel, the cast and the tiles' stencil.
  struct Programs
  {
    vtkShaderProgram* Peel = nullptr;
    vtkShaderProgram* Cast = nullptr;
    vtkShaderProgram* Mask = nullptr;
  };
  /// The screen tiles of a frame (one covering the viewport without tiles).
  struct TileGrid
  {
    int Size = 0;
    int Count[2] = { 0, 0 };
    int Tiles = 0;
  };

  /// The ray mesh and the table: each when its version changed.
  void Upload(const RayFrame& frame);
  /// The programs (nullptr members, with an error, when one did not build).
  bool MakePrograms(
    vtkOpenGLRenderWindow* window, const RayFrame& frame, Programs& programs, bool isoShade);
  /// Every uniform of the three programs for this frame.
  void SetUniforms(vtkOpenGLRenderWindow* window, const Programs& programs, const RayFrame& frame,
    const TileGrid& grid);
  /// Per pixel no entry, no ray, opacity 0; the counts zeroed; the buffers and images bound.
  void ClearRays(const TileGrid& grid, int width, int height);
  /// One pass's peel: the nearest front-facing boundary entry beyond each ray's reach.
  void Peel(vtkOpenGLRenderWindow* window, const Programs& programs, const RayFrame& frame,
    const TileGrid& grid, int pass, int sectionTriangles, vtkHAVSGLQueries& queries);
  /// One pass's cast: the rays walked from their entries, the colour under the result.
  void Cast(vtkOpenGLRenderWindow* window, const Programs& programs, const RayFrame& frame,
    const TileGrid& grid, int pass);
  /// The frame's counts: rays, cells, fold re-entries, the tiles' passes, the GPU times.
  void ReadCounts(const TileGrid& grid, vtkHAVSGLQueries& queries, RayCounts* counts);
  /**
   * The frame just drawn written as a frame case into `directory`
   * (Apps/GPUBench/README.md: the Core arrays, the shaders, the uniforms, the
   * table, the float result); `counts`: the frame's passes, rays, cells
   * crossed, fold re-entries. False, with `error` set, when it cannot.
   */
  bool Capture(const std::string& directory, const RayFrame& frame, const Programs& programs,
    const TileGrid& grid, const RayCounts& counts, std::string& error);

  vtkNew<vtkHAVSGLMapperResources> Resources; // the window, the table, the targets
  struct GLObjects;                           // the mapper's own buffers and images
  GLObjects* GL = nullptr;                    // (owned and released by Resources)
};

VTK_ABI_NAMESPACE_END
#endif
