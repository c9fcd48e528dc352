/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceOrderPolicy.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFaceOrderPolicy
 * @brief   Which face order a frame draws, made only when its inputs changed.
 *
 * Plain C++, no OpenGL. Owns the two orders of vtkHAVSVolumeMapper and the
 * choice between them:
 * - Centroid: HAVS's sort of the face centroids by distance to the eye
 *   (vtkHAVSFaceSorter; Callahan et al. 2005), nearly sorted, the k-buffer
 *   finishes it;
 * - MPVO: the exact front-to-back order of the tetrahedra (Williams 1992,
 *   vtkHAVSVisibilityOrder), with the rays' re-entries of a non-convex mesh
 *   from the boundary layers (after Krishnan, Silva and Wei 2001) or the
 *   convexification (Kraus and Ertl 2001);
 * - Automatic: the centroid order drawn as a probe (counted, not composited)
 *   while the k-buffer keeps up with it; the first probe with order
 *   violations makes MPVO the order for this mesh, k and path, and the frame
 *   is drawn again.
 *
 * Each order is made again only when what it depends on changed: the mesh
 * (its build time), the view in the grid's coordinates (eye, direction,
 * projection; and, for the boundary layers, the pixels they are sampled at).
 * Every key is a value compared with ==, nothing else. GetDrawTriangles()
 * gives the faces' point ids in draw order, gathered once per new order.
 */
#ifndef vtkHAVSFaceOrderPolicy_h
#define vtkHAVSFaceOrderPolicy_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h"      // For export macro
#include "vtkHAVSMemory.h"          // For vtkHAVSMemory::Bytes
#include "vtkHAVSVisibilityOrder.h" // For ViewKey
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"

#include <array>      // For std::array
#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <utility>    // For std::move
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFaceSorter;
class vtkHAVSMesh;
class vtkHAVSViewFrame;
class vtkHAVSVisibilityOrder;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSFaceOrderPolicy : public vtkObject
{
public:
  static vtkHAVSFaceOrderPolicy* New();
  vtkTypeMacro(vtkHAVSFaceOrderPolicy, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The order asked for (vtkHAVSVolumeMapper::VisibilityOrders) and the
  /// exact order's non-convex method (vtkHAVSVisibilityOrder::NonConvexMethods).
  vtkSetMacro(VisibilityOrder, int);
  vtkGetMacro(VisibilityOrder, int);
  vtkSetMacro(NonConvexMethod, int);
  vtkGetMacro(NonConvexMethod, int);
  ///@}

  /// What a frame draws first: an order, and whether it is Automatic's probe.
  struct Plan
  {
    int Order = 0;      ///< VisibilityOrders: Centroid or MPVO; -1 none (no order needed)
    bool Probe = false; ///< draw it counted, composite it only if it has no violation
  };

  /**
   * The plan of a frame. `needsOrder`: the blend mode composites (the
   * extremum modes need none). `canProbe`: Automatic may draw a probe (not
   * for a raster-bound benchmark frame). `k` and `path` are part of what
   * Automatic's choice holds for.
   */
  Plan Begin(vtkHAVSMesh* mesh, int k, int path, bool needsOrder, bool canProbe);

  /**
   * Automatic: the probe had `violations`; when there were any, MPVO becomes
   * the order (for this mesh, k and path) and the returned plan (MPVO, no
   * probe) is what to draw again. Returns the plan to draw next, Order -1
   * when nothing needs drawing again.
   */
  Plan ProbeResult(vtkIdType violations);

  /**
   * Makes the order of `plan` for the view (reused when its inputs are
   * unchanged) and gathers the draw triangles. `grid` is the mesh's input
   * (the exact order reads its points). Returns false when the exact order
   * could not be made (the centroid order is then used, with an error).
   */
  bool Prepare(
    const Plan& plan, vtkHAVSMesh* mesh, vtkUnstructuredGrid* grid, const vtkHAVSViewFrame& view);

  /**
   * The cells the transfer function leaves visible (vtkHAVSCellVisibility:
   * per grid cell id; null: all), and when that set last changed. From the
   * next Prepare(), only faces with a visible cell are gathered; a face
   * between a visible and an invisible cell is a boundary face, wound out of
   * the visible one. A new set gathers again without a new sort.
   */
  void SetCellVisibility(const std::vector<uint8_t>* visible, vtkMTimeType version);

  /**
   * The cells the frame cannot see (vtkHAVSViewCulling: per grid cell id, 1
   * culled; null: none), and when that set last changed. A face both of whose
   * cells are culled is neither ordered (the centroid sort keys only the
   * other faces, the exact order skips the culled cells:
   * vtkHAVSVisibilityOrder::SetSkippedCells) nor gathered; a face both of
   * whose cells are culled or hidden is not gathered. Culling makes no
   * boundary face (a culled cell's faces lie outside the image or the
   * clipped volume).
   */
  void SetCellCulling(const std::vector<uint8_t>* culled, vtkMTimeType version);

  /**
   * The level of detail: per face of the face set its rank among the internal
   * faces (vtkHAVSInternalFaceRanking; null: every face), and how many of them
   * are drawn (those ranked below `limit`); `version` changes with the ranks.
   * Boundary faces, and the faces that become boundary faces between visible
   * and invisible cells, are always gathered. A new limit gathers again
   * without a new sort.
   */
  void SetFaceSubset(const std::vector<uint32_t>* ranks, uint32_t limit, vtkMTimeType version);

  ///@{
  /**
   * The faces in draw order: 3 point ids each, and per face 0 (internal), 1
   * (a boundary face as the face set winds it: out of the mesh) or 2 (a face
   * between a visible and an invisible cell wound the other way than the face
   * set's, so that it points out of the visible cell: the vertices' cell-scalar
   * pairs are swapped with it).
   */
  const std::vector<uint32_t>& GetDrawTriangles() const { return this->DrawTriangles; }
  const std::vector<uint8_t>& GetDrawBoundaryFlags() const { return this->DrawBoundary; }
  /// Changes whenever the draw triangles do.
  vtkMTimeType GetDrawOrderVersion() const { return this->DrawOrderTime.GetMTime(); }
  ///@}

  ///@{
  /// The last Prepare(): the order drawn (-1 none), whether it was reused
  /// (no new sort; the faces may have been gathered again for a new set of
  /// visible cells), the seconds it took (sort and gather).
  vtkGetMacro(LastOrder, int);
  vtkGetMacro(LastReused, bool);
  vtkGetMacro(LastSeconds, double);
  /// The part of LastSeconds that gathered the draw triangles in the new order.
  vtkGetMacro(LastGatherSeconds, double);
  /// Faces in the order drawn (0 without one): fewer than the mesh's when
  /// culled cells were left out of it.
  vtkGetMacro(LastOrderedFaces, vtkIdType);
  /// The exact order's cycle breaks, boundary relations and their seconds.
  vtkIdType GetLastCycleBreaks() const;
  vtkIdType GetLastBoundaryRelations() const;
  double GetLastBoundaryLayerSeconds() const;
  ///@}

  /// Called with 0 … 1 while the exact order's adjacency is built (once per
  /// mesh): the mapper's UpdateProgress.
  void SetProgressCallback(std::function<void(double)> progress)
  {
    this->Progress = std::move(progress);
  }

  /// The next Prepare() makes its order again even for an unchanged view.
  void Invalidate();

  vtkHAVSFaceSorter* GetCentroidSorter() { return this->Centroid; }
  vtkHAVSVisibilityOrder* GetExactOrder() { return this->Exact; }

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;
  /// The same in three parts: the centroid sort, the exact (MPVO) order, the drawn faces.
  void AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const;

protected:
  vtkHAVSFaceOrderPolicy();
  ~vtkHAVSFaceOrderPolicy() override;

private:
  vtkHAVSFaceOrderPolicy(const vtkHAVSFaceOrderPolicy&) = delete;
  void operator=(const vtkHAVSFaceOrderPolicy&) = delete;

  /// What Automatic's choice holds for.
  struct AutomaticKey
  {
    vtkMTimeType Mesh = 0;
    int K = 0;
    int Path = 0;
    bool operator==(const AutomaticKey& o) const
    {
      return this->Mesh == o.Mesh && this->K == o.K && this->Path == o.Path;
    }
  };

  const std::vector<uint32_t>* MakeExactOrder(
    vtkHAVSMesh* mesh, vtkUnstructuredGrid* grid, const vtkHAVSViewFrame& view, bool& changed);
  void Gather(vtkHAVSMesh* mesh, const std::vector<uint32_t>* order);

  int VisibilityOrder = 0;
  int NonConvexMethod = 1;

  vtkNew<vtkHAVSFaceSorter> Centroid;
  vtkNew<vtkHAVSVisibilityOrder> Exact;
  std::function<void(double)> Progress;
  vtkMTimeType ExactMeshTime = 0; // the mesh the exact order's adjacency was built for
  vtkHAVSVisibilityOrder::ViewKey LastExactKey;
  bool ExactValid = false;

  AutomaticKey LastAutomaticKey;
  bool AutomaticExact = false;
  bool AutomaticDecided = false;

  std::vector<uint32_t> DrawTriangles;
  std::vector<uint8_t> DrawBoundary;
  vtkTimeStamp DrawOrderTime;
  int GatheredOrder = -2; // the order the draw triangles hold (-1: identity)
  vtkMTimeType GatheredMesh = 0;
  const std::vector<uint8_t>* Visible = nullptr;
  vtkMTimeType VisibilityVersion = 0;
  vtkMTimeType GatheredVisibility = 0;
  const std::vector<uint8_t>* Culled = nullptr;
  vtkMTimeType CullingVersion = 0;
  vtkMTimeType GatheredCulling = 0;
  // The faces the centroid sort orders when not all are drawn: those with a
  // cell that is not culled and, with the level of detail's subset, only the
  // boundary faces (of the mesh, or between a visible and an invisible cell)
  // and the internal faces ranked below the limit (the faces Gather keeps:
  // a subset frame sorts what it draws, not every face); for the mesh,
  // culling, visibility and subset they were listed for.
  void ListSortedFaces(vtkHAVSMesh* mesh);
  std::vector<uint32_t> UnculledFaces;
  vtkMTimeType UnculledMesh = 0;
  vtkMTimeType UnculledCulling = 0;
  vtkMTimeType UnculledVisibility = 0;
  vtkTimeStamp UnculledTime;
  struct SubsetKey
  {
    const std::vector<uint32_t>* Ranks = nullptr;
    uint32_t Limit = 0;
    vtkMTimeType Version = 0;
    bool operator==(const SubsetKey& o) const
    {
      return this->Ranks == o.Ranks && this->Limit == o.Limit && this->Version == o.Version;
    }
  };
  SubsetKey Subset;
  SubsetKey GatheredSubset;
  SubsetKey UnculledSubset;

  int LastOrder = -1;
  bool LastReused = false;
  double LastSeconds = 0.0;
  double LastGatherSeconds = 0.0;
  vtkIdType LastOrderedFaces = 0;
};

VTK_ABI_NAMESPACE_END
#endif
