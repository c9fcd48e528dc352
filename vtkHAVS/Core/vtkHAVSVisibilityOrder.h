/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVisibilityOrder.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSVisibilityOrder
 * @brief   An exact object-space face order: Williams' MPVO (1992) for HAVS.
 *
 * Plain C++, no OpenGL. Build() finds, once per mesh, the two tetrahedra of
 * every internal face of a vtkHAVSFaceSet and on which side of each face's
 * plane its first tetrahedron lies. Sort() then, per view, orients every
 * internal face by the side of its plane the eye is on (the plane made again
 * from the face's points in double precision, as Build() made it: 32 bytes a
 * face not kept; the tetrahedron on
 * the eye's side is in front), sorts the tetrahedra topologically front to
 * back (Kahn), and emits each face when the tetrahedron behind it is visited
 * (a boundary face with its only tetrahedron: entries first, then exits).
 * For a convex mesh without visibility cycles the faces come out so that
 * the fragments along every ray arrive in depth order: k = 1 suffices up to
 * fragments at equal distance. O(faces) per view.
 *
 * Cycles (the sort stalls with cells left) are broken locally: the
 * unvisited cell with the fewest unvisited predecessors is taken next;
 * GetNumberOfCycleBreaks() counts them.
 *
 * Non-convex meshes (vtkHAVSFaceSet::IsConvex false): where a ray leaves the
 * mesh and enters it again, the cell it enters must come after the one it
 * left, which no shared face says. Two ways to add those relations
 * (SetNonConvexMethod), so that they can be compared:
 * - Convexification (Röttger, Guthe, Schieber and Ertl 2004, seed 004; after
 *   Williams' imaginary cells and Kraus and Ertl 2001): the space around the mesh is
 *   cut into convex imaginary cells (vtkHAVSConvexification, once per mesh);
 *   they join the sort through the boundary faces and the planes between
 *   them, and draw nothing.
 * - BoundaryLayers (after Krishnan, Silva and Wei 2001, seed 003): per view, the
 *   boundary faces are rasterized (vtkHAVSFaceRasterizer, exactly, at the
 *   frame's pixel centres, SetViewSampling) and sorted by depth at every pixel; each exit followed
 *   by an entry gives the relation "cell left before cell entered". Exact at
 *   the pixels the k-buffer composites, whatever the shape of the gaps.
 *   Where the boundary is not closed and consistently wound (inverted cells),
 *   the convexification warns and the boundary layers are used instead.
 * - Ignore: MPVO alone (exact only where no ray re-enters the mesh).
 * Seams (two boundary faces at the same place, of two tetrahedra whose
 * points are duplicated, as on the cut of an O-grid) join their tetrahedra
 * like an internal face, whatever the method (GetNumberOfSeamFaces()).
 *
 * Eye and direction of projection are given in the grid's (model)
 * coordinates; a parallel projection orients by the direction alone.
 */
#ifndef vtkHAVSVisibilityOrder_h
#define vtkHAVSVisibilityOrder_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <array>      // For std::array
#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <utility>    // For std::pair
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSConvexification;
class vtkHAVSFaceRasterizer;
class vtkHAVSFaceSet;
class vtkHAVSViewFrame;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSVisibilityOrder : public vtkObject
{
public:
  static vtkHAVSVisibilityOrder* New();
  vtkTypeMacro(vtkHAVSVisibilityOrder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The adjacency of `faces` (built from `grid`, whose points are read; the
   * face set is kept and must not be built again before the next Build()).
   * Each tetrahedron's faces are found by binary search in the face set's
   * order (its faces sorted by their sorted point ids), in parallel.
   * `progress`, when given, is called with 0 … 1. Returns false, with an
   * error, when a tetrahedron's face is not in the set.
   */
  bool Build(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid)
  {
    return this->Build(faces, grid, nullptr);
  }
  bool Build(
    vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid, const std::function<void(double)>& progress);

  enum NonConvexMethods
  {
    NonConvexIgnore = 0,
    NonConvexBoundaryLayers = 1,
    NonConvexConvexification = 2
  };

  ///@{
  /// How rays that leave and re-enter a non-convex mesh are ordered (default
  /// BoundaryLayers). Unused for a convex mesh.
  vtkSetClampMacro(NonConvexMethod, int, NonConvexIgnore, NonConvexConvexification);
  vtkGetMacro(NonConvexMethod, int);
  ///@}

  /**
   * The frame the next Sort() is for: grid (model) -> clip matrix (row-major,
   * as vtkMatrix4x4) and viewport size in pixels. Used by BoundaryLayers.
   */
  void SetViewSampling(const double modelToClip[16], int width, int height);

  /// Whether the mesh given to Build() is convex (no relations needed across gaps).
  bool IsMeshConvex() const { return this->MeshConvex; }

  /**
   * What an order was made for: equal keys give the same Sort() result. The
   * view's pixel sampling counts only where the boundary layers sample it
   * (a non-convex mesh).
   */
  struct ViewKey
  {
    vtkMTimeType Mesh = 0;
    std::array<double, 3> Eye{};
    std::array<double, 3> Direction{};
    bool Parallel = false;
    int Method = -1;
    std::array<double, 16> GridToClip{};
    int Width = 0;
    int Height = 0;
    vtkMTimeType Skip = 0; // the skipped cells' version (SetSkippedCells)
    bool operator==(const ViewKey& o) const
    {
      return this->Mesh == o.Mesh && this->Eye == o.Eye && this->Direction == o.Direction &&
        this->Parallel == o.Parallel && this->Method == o.Method &&
        this->GridToClip == o.GridToClip && this->Width == o.Width && this->Height == o.Height &&
        this->Skip == o.Skip;
    }
  };
  /// The key of a Sort() for `view` with `method`, of the mesh built at `meshTime`.
  ViewKey MakeViewKey(vtkMTimeType meshTime, const vtkHAVSViewFrame& view, int method) const;

  /**
   * The face order for a view (eye and direction in model coordinates);
   * front to back.
   */
  void Sort(const double eye[3], const double direction[3], bool parallel);

  /**
   * Cells the next Sort() leaves out (per grid cell id of the face set's
   * GetTetrahedronCells(), 1 skipped; null: none), and when that set last
   * changed. Only for cells the frame cannot see because each lies wholly
   * outside one half-space whose outside is never drawn (vtkHAVSViewCulling:
   * a frustum plane, or a clipping plane's discarded side). A ray crosses
   * such a plane once, so the part of every ray that reaches the image runs
   * through kept cells only, and the relations between kept cells (shared
   * faces, seams, boundary layers, imaginary cells) order it exactly. Cells
   * hidden by the transfer function must not be skipped here: the order
   * across the gaps they leave runs through them. A face between a kept and
   * a skipped cell is ordered as an exit of the kept one; a face of skipped
   * cells only is left out of GetOrder() (GetNumberOfSkippedFaces()).
   */
  void SetSkippedCells(const std::vector<uint8_t>* skipped, vtkMTimeType version);
  /// Faces the last Sort() left out: every cell they border was skipped.
  vtkGetMacro(NumberOfSkippedFaces, vtkIdType);

  /// The two tetrahedra of a face (-1: none; a boundary face has only the first).
  void GetFaceTetrahedra(vtkIdType face, vtkIdType cells[2]) const
  {
    cells[0] = static_cast<vtkIdType>(this->FaceCells[2 * face]);
    cells[1] = static_cast<vtkIdType>(this->FaceCells[2 * face + 1]);
  }

  /// Face indices, first drawn first.
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }

  /**
   * The tetrahedra (indices into the face set's GetTetrahedra()) in the same
   * sort, front to back: the cell order of vtkHAVSCellProjectionMapper. A
   * cycle break (GetNumberOfCycleBreaks) takes one tetrahedron out of order.
   */
  const std::vector<uint32_t>& GetCellOrder() const { return this->CellOrder; }

  /// Tetrahedra taken out of order to break visibility cycles in the last Sort().
  vtkGetMacro(NumberOfCycleBreaks, vtkIdType);

  /// Seconds the last Sort() took (without a convexification it triggered).
  vtkGetMacro(LastSortSeconds, double);

  /// Internal faces whose two tetrahedra lie on the same side (inverted or
  /// overlapping cells), found by Build(): no order is exact across them.
  vtkGetMacro(NumberOfFoldedFaces, vtkIdType);
  bool IsFaceFolded(vtkIdType face) const { return (this->FaceFlags[face] & FaceFolded) != 0; }

  /// Pairs of boundary faces found at the same place (seams) by Build().
  vtkIdType GetNumberOfSeamFaces() const
  {
    return static_cast<vtkIdType>(this->SeamFaces.size() / 2);
  }

  /// Convexification: imaginary cells, and the seconds it took (once per mesh).
  vtkGetMacro(NumberOfImaginaryCells, vtkIdType);
  vtkGetMacro(ConvexificationSeconds, double);

  /// BoundaryLayers: relations found in the last Sort() and the seconds they took.
  vtkGetMacro(NumberOfBoundaryRelations, vtkIdType);
  vtkGetMacro(LastBoundaryLayerSeconds, double);

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSVisibilityOrder();
  ~vtkHAVSVisibilityOrder() override;

private:
  vtkHAVSVisibilityOrder(const vtkHAVSVisibilityOrder&) = delete;
  void operator=(const vtkHAVSVisibilityOrder&) = delete;

  void BuildConvexification();
  /// Face f's plane (n, d: n.x + d > 0 on the far side from FaceCells[2f]'s
  /// tetrahedron), from its points in double precision, the same every time.
  void FacePlane(size_t f, double plane[4]) const;
  /// Whether the face set is still the one Build() read (an error if not).
  bool FacesUnchanged();
  void BoundaryLayerRelations(const double eye[3], const double direction[3], bool parallel,
    std::vector<std::pair<uint32_t, uint32_t>>& relations);

  std::vector<int32_t> FaceCells;        // 2 per face: the tetrahedra (-1: none; at most 2^31 - 1)
  std::vector<uint32_t> CellFaces;       // 4 per tetrahedron
  vtkSmartPointer<vtkHAVSFaceSet> Faces; // the face set built on (its vertices and cells read)
  vtkMTimeType FacesBuildTime = 0;       // its build time then
  const std::vector<uint8_t>* Skipped = nullptr; // per grid cell id (SetSkippedCells)
  vtkMTimeType SkippedVersion = 0;
  vtkIdType NumberOfSkippedFaces = 0;
  std::vector<uint32_t> Order;
  std::vector<uint32_t> CellOrder;
  std::vector<double> Points;                 // the grid's points (3 per point)
  std::vector<uint32_t> BoundaryFaces;        // face ids of the boundary faces
  std::vector<uint32_t> BoundaryFaceVertices; // 3 per boundary face, wound outward
  std::vector<uint32_t> SeamFaces; // pairs of boundary faces at the same place (duplicated points)
  bool MeshConvex = true;
  vtkIdType NumberOfFoldedFaces = 0;
  enum FaceFlagBits : uint8_t
  {
    FaceFolded = 1,  // both tetrahedra on one side of the plane
    FaceFlipped = 2, // the plane's normal is the winding's reversed
  };
  std::vector<uint8_t> FaceFlags; // per face
  int NonConvexMethod = NonConvexBoundaryLayers;
  double ModelToClip[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  int SampleSize[2] = { 0, 0 };
  vtkSmartPointer<vtkHAVSConvexification> Convexification;
  vtkSmartPointer<vtkHAVSFaceRasterizer> Rasterizer;
  bool ConvexificationBuilt = false;
  vtkIdType NumberOfImaginaryCells = 0;
  double ConvexificationSeconds = 0.0;
  vtkIdType NumberOfBoundaryRelations = 0;
  double LastBoundaryLayerSeconds = 0.0;
  vtkIdType NumberOfCycleBreaks = 0;
  double LastSortSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif
