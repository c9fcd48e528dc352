/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRayCastMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRayCastMapper
 * @brief   GPU ray casting through the tetrahedra, with depth-peeled re-entries.
 *
 * The second mapper of vtkHAVS after HAVS, from Bernardon, Pagot, Comba and
 * Silva, "GPU-based Tiled Ray Casting using Depth Peeling" (2005, seed 002),
 * after Weiler, Kraus, Merz and Ertl (2003). No sorting: per pixel the ray
 * starts at the nearest front-facing boundary face (its tetrahedron known
 * per face), walks from cell to cell through the face neighbours (the exit
 * face: the nearest forward intersection among the cell's face planes,
 * computed in double precision on the CPU, walked in float in model
 * coordinates on the GPU), integrates each segment from the shared
 * pre-integration table (the scalar at both ends from the cell's linear
 * field) and composites front to back, until it leaves the mesh, reaches
 * opaque geometry or a clipping plane, or its opacity reaches
 * EarlyRayTerminationOpacity.
 *
 * Non-convex meshes, without convexification: a ray that leaves the mesh
 * re-enters at the next layer of front-facing boundary faces beyond its
 * exit, found by depth peeling. Passes repeat until one starts no ray (all
 * of them, counted: GetLastPeelPasses()); MaximumPeelPasses limits them (a
 * negative control: one pass on a mesh that needs more).
 *
 * Same inputs, scalars, mesh and table as the other mappers
 * (vtkHAVSMapperBase, whose Render() calls RenderView()), the volume's matrix, perspective and
 * parallel cameras, opaque geometry, up to 6 clipping planes (each ray clipped to them). The camera
 * inside the mesh: where the near plane cuts it (the GL near clip removes the entry faces there)
 * the rays start on the near plane's section (vtkHAVSFramePlanes, each triangle with its cell),
 * drawn with the entries of the first pass. Screen tiles: the ray-casting pass works only in the
 * tiles where rays start, with per-tile pass counts. Blend modes: composite, maximum and minimum
 * intensity, additive.
 *
 * The mesh's layout is vtkHAVSRayCastMesh (96 bytes per tetrahedron).
 *
 * Abstract: New() gives the graphics layer's override
 * (vtkOpenGLHAVSRayCastMapper), as vtkHAVSVolumeMapper does.
 */
#ifndef vtkHAVSRayCastMapper_h
#define vtkHAVSRayCastMapper_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMapperBase.h"

#include <functional> // For std::function
#include <memory>     // For std::unique_ptr
#include <string>     // For std::string
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSRayCastMesh;

class VTKHAVSCORE_EXPORT vtkHAVSRayCastMapper : public vtkHAVSMapperBase
{
public:
  /// The graphics layer's override (vtkOpenGLHAVSRayCastMapper); nullptr without one.
  static vtkHAVSRayCastMapper* New();
  vtkTypeMacro(vtkHAVSRayCastMapper, vtkHAVSMapperBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Blend modes (vtkHAVSMapperBase): composite (default), maximum and
  // minimum intensity (the extremal scalar along the ray in the mesh coloured
  // by the transfer function), additive (VTK's: the integral of tau(s) s,
  // clamped to 1, grey).

  ///@{
  /// A ray stops once its opacity reaches this (default 0.999, as vtkHAVSVolumeMapper).
  vtkSetClampMacro(EarlyRayTerminationOpacity, double, 0.0, 1.0);
  vtkGetMacro(EarlyRayTerminationOpacity, double);
  ///@}

  ///@{
  /**
   * The most depth-peeling passes per frame (each starts the rays at the
   * next layer of boundary entries); 0 (the default): as many as the mesh
   * needs, until a pass starts no ray (at most 1024).
   */
  vtkSetClampMacro(MaximumPeelPasses, int, 0, 1024);
  vtkGetMacro(MaximumPeelPasses, int);
  ///@}

  ///@{
  /// Testing aid (a negative control): each cell's neighbours rotated by one
  /// face (vtkHAVSRayCastMesh::BreakNeighboursForTesting). Off by default.
  void SetBrokenNeighboursForTesting(bool broken);
  vtkGetMacro(BrokenNeighboursForTesting, bool);
  ///@}

  ///@{
  /**
   * Screen tiles (the seed's tiling): the ray-casting pass draws only the
   * tiles of TileSize x TileSize pixels in which the pass's peeling found an
   * entry, and each tile counts its passes (GetLastTilePasses()); from the
   * second pass on, the peeling draws only in the tiles where a ray left the
   * mesh in the pass before (a stencil of them; no other ray can start
   * again). On by default, 16 pixels; off: full-viewport passes (the same
   * image, bit for bit).
   */
  vtkSetMacro(Tiles, bool);
  vtkGetMacro(Tiles, bool);
  vtkBooleanMacro(Tiles, bool);
  vtkSetClampMacro(TileSize, int, 4, 256);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /**
   * The last frame's tiles: their grid (columns, rows) and, per tile (row
   * by row, bottom first), the passes in which rays started there (0: none,
   * no ray-casting work there; the largest is GetLastPeelPasses()).
   */
  const int* GetLastTileGrid() const { return this->LastTileGrid; }
  const std::vector<int>& GetLastTilePasses() const { return this->LastTilePasses; }
  /// Per peeling pass drawn (the last, which started no ray, included): the
  /// boundary's fragments that took part (passed the tiles' stencil).
  const std::vector<long long>& GetLastPeelFragments() const { return this->LastPeelFragments; }
  ///@}

  ///@{
  /**
   * Re-entries across folds of the boundary (on by default; off only as a
   * negative control). Where the boundary folds (an exit face and an entry
   * face sharing an edge: a crease), a ray that leaves the mesh may come
   * back in through the entry face a hair from that edge, where the
   * rasterizer may not cover its pixel, so that the peeling never finds the
   * entry and the rest of the ray is lost. On: a ray that leaves through a
   * boundary face walks around the face's edge nearest the exit point
   * (through the face neighbours) to the boundary face on the other side
   * and, if the ray passes through that face's cell beginning within a
   * thousandth of the eye distance after the exit, goes on there
   * (GetLastFoldReentries() counts them).
   */
  vtkSetMacro(FoldReentries, bool);
  vtkGetMacro(FoldReentries, bool);
  vtkBooleanMacro(FoldReentries, bool);
  ///@}

  /// Rays that went on across a fold of the boundary in the last frame.
  vtkGetMacro(LastFoldReentries, vtkIdType);

  ///@{
  /**
   * The last frame: depth-peeling passes that started rays, rays started
   * over all passes, cells crossed over all rays (segments integrated),
   * seconds of the draw (with the GPU finished), and of it the GPU's seconds
   * in the peeling draws and in the ray casts (GL timestamp queries around
   * each stage of each pass; -1 where the context has no timer).
   */
  vtkGetMacro(LastPeelPasses, int);
  vtkGetMacro(LastRaysStarted, vtkIdType);
  vtkGetMacro(LastCellsCrossed, vtkIdType);
  vtkGetMacro(LastDrawSeconds, double);
  vtkGetMacro(LastPeelSeconds, double);
  vtkGetMacro(LastCastSeconds, double);
  ///@}

#ifndef __VTK_WRAP__
  /// The compact mesh layout of the last frame (nullptr before one).
  const vtkHAVSRayCastMesh* GetRayCastMesh() const { return this->RayMesh.get(); }
#endif

  /// What the graphics layer draws in one frame.
  struct RayFrame
  {
    const vtkHAVSViewFrame* View = nullptr;
    vtkHAVSMesh* Mesh = nullptr;
    const vtkHAVSRayCastMesh* RayMesh = nullptr;
    vtkMTimeType MeshVersion = 0; ///< changes whenever RayMesh does
    vtkHAVSPreIntegrationTable* Table = nullptr;
    vtkMTimeType TableVersion = 0;
    vtkHAVSFramePlanes* Planes = nullptr;
    bool Opaque = false;
    bool KeepResult = false;
    float TerminationOpacity = 0.999f;
    int MaximumPasses = 1024;
    int TileSize = 16; ///< 0: no tiles
    int Blend = 0;     ///< the blend mode
    bool FoldReentries = true;
    /// Makes RayMesh's cell records again when they were freed after an
    /// upload and the GPU needs them (its buffers were released).
    std::function<void()> RestoreCells;
  };
  /// What the graphics layer counted in one frame.
  struct RayCounts
  {
    int Passes = 0;
    long long Rays = 0;
    long long Cells = 0;
    long long FoldReentries = 0;
    double Seconds = 0.0;
    double PeelSeconds = -1.0; ///< GPU time in the peeling draws (-1: not measured)
    double CastSeconds = -1.0; ///< GPU time in the casts (-1: not measured)
    int TileGrid[2] = { 0, 0 };
    std::vector<int> TilePasses;
    std::vector<long long> PeelFragments; ///< per peeling pass drawn
  };

protected:
  vtkHAVSRayCastMapper();
  ~vtkHAVSRayCastMapper() override;

  void ResetLastFrame() override;
  void AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const override;
  vtkHAVSMemory::Part GetLargestGPUBufferNeed() const override;
  void MeshPrepared(int update, bool rebuilt) override;
  void RenderView(vtkRenderer* renderer, vtkVolume* volume, const vtkHAVSViewFrame& view) override;

  /// The graphics layer: draws one frame (false, with an error, when it cannot).
  virtual bool DrawRays(vtkRenderer* renderer, const RayFrame& frame, RayCounts* counts);

private:
  vtkHAVSRayCastMapper(const vtkHAVSRayCastMapper&) = delete;
  void operator=(const vtkHAVSRayCastMapper&) = delete;

  /// The ray mesh's fields (the cell records) from the mesh (a new time step, RestoreCells).
  void UpdateRayFields();

  double EarlyRayTerminationOpacity = 0.999;
  int MaximumPeelPasses = 0;
  bool BrokenNeighboursForTesting = false;
  bool FoldReentries = true;
  vtkIdType LastFoldReentries = 0;
  bool Tiles = true;
  int TileSize = 16;
  int LastTileGrid[2] = { 0, 0 };
  std::vector<int> LastTilePasses;
  std::vector<long long> LastPeelFragments;
  int LastPeelPasses = 0;
  vtkIdType LastRaysStarted = 0;
  vtkIdType LastCellsCrossed = 0;
  double LastDrawSeconds = 0.0;
  double LastPeelSeconds = -1.0;
  double LastCastSeconds = -1.0;

  std::unique_ptr<vtkHAVSRayCastMesh> RayMesh;
  vtkTimeStamp RayMeshTime;
  bool RayMeshBroken = false; // the layout holds the broken table
};

VTK_ABI_NAMESPACE_END
#endif
