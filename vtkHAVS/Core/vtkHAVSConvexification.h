/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSConvexification.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSConvexification
 * @brief   Imaginary convex cells that fill the space around a non-convex mesh.
 *
 * Plain C++, no OpenGL. MPVO orders the cells of a mesh through their shared
 * faces, which is exact only for a convex mesh: where a ray leaves the mesh
 * and re-enters it, nothing relates the two parts. Following Röttger, Guthe,
 * Schieber and Ertl 2004 (seed 004)
 * (section 6 "Convexification of Tetrahedral Grids", after Williams' idea of
 * imaginary cells), the space around the mesh, inside a bounding box, is
 * filled with imaginary cells so that mesh and imaginary cells tile the box;
 * MPVO then orders real and imaginary cells together. As in the seed, the imaginary cells are
 * convex polyhedra, not tetrahedra, obtained by cutting the exterior volume
 * with planes through the boundary triangles.
 *
 * Here the cuts form a solid-leaf BSP tree (autopartition) of the boundary
 * triangles inside a root box, the bounds of the points enlarged by 10 % of
 * their diagonal on every side. Each node's plane is the plane of one of its
 * triangles (the seed's selection heuristic: up to 8 random candidates, the
 * one whose plane straddles the fewest other triangles wins, ties to the
 * more balanced cut); the triangles coplanar with it and of the same
 * orientation stay at the node, those of the opposite orientation go behind
 * it, straddling ones are split into convex pieces. Vertices closer than a
 * tolerance eps to a plane are snapped onto it (as the seed does), so no
 * sliver pieces appear: eps is 1e-9 of the box diagonal, or 16 rounding
 * errors of the largest coordinate where every coordinate is a float (VTK's
 * float points), at most 1e-5 of the diagonal.
 *
 * Coplanarity is decided once, before the tree, not plane by plane: the
 * triangles are grouped into plane classes (largest first, a triangle joins
 * the class whose first plane has its three vertices within 16 eps) and
 * every triangle takes its class's plane, the least-squares plane of the
 * class's vertices, oriented like the triangle. Pieces and portal polygons
 * of a node's class lie on its plane by definition; the node's tolerance
 * covers its class's vertices. (With each triangle's own plane and 1e-9,
 * faces coplanar only up to float rounding, e.g. those of a voxel grid of
 * spacing 1/24 or turned by a rotation, fell on both sides of each other's
 * planes: sliver cells and pieces reaching OUT leaves they do not touch
 * made false relations and thousands of cycles in the MPVO order.)
 *
 * The front of a plane is the outer side
 * of its triangle; a node with nothing in front gets an OUT leaf there, an
 * imaginary cell (the convex region of the leaf, clipped by the root box);
 * nothing behind gives an IN leaf (inside the mesh). The tree is built
 * iteratively: its depth reaches the number of triangles on convex parts.
 *
 * Internal double walls (coincident boundary triangles of opposite
 * orientations with the mesh on both sides, as a mesh cut whose points are
 * duplicated gives, e.g. the seams of PLOT3D grids) bound nothing: where
 * coplanar pieces of both orientations overlap at a node, the overlap is
 * dropped from both (the seed's "remove all triangles that appear twice");
 * a node left with no piece of its own gets an IN leaf in front. Triangles
 * wholly inside such a wall have no imaginary cell.
 *
 * Adjacency, for MPVO:
 * - triangle-cell: the pieces stored at a node are pushed down its front
 *   subtree; a piece that reaches an OUT leaf relates its triangle to it.
 * - cell-cell (portals): the node's region cut by its plane (a polygon,
 *   clipped by the root box and the ancestors' half-spaces) is pushed down
 *   the front subtree and each piece that reaches an OUT leaf down the back
 *   subtree; pieces with OUT leaves on both sides are portals.
 * Pushes and clips first test a polygon's bounding sphere against the
 * plane, so a chain of nodes costs O(1) per node for a polygon far away.
 *
 * Input: boundary triangles wound so that (p1 - p0) x (p2 - p0) points out
 * of the mesh; the surface must be closed (and consistently wound) for the
 * IN/OUT labels to be right. Degenerate triangles (area at most 1e-12 of the
 * squared box diagonal) are left out and counted; pieces of area at most
 * 1e-18 of it are ignored in the adjacency. Plain C++, single-threaded.
 */
#ifndef vtkHAVSConvexification_h
#define vtkHAVSConvexification_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <memory>  // For std::unique_ptr
#include <utility> // For std::pair
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSConvexification : public vtkObject
{
public:
  static vtkHAVSConvexification* New();
  vtkTypeMacro(vtkHAVSConvexification, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * points: 3 doubles per point. triangles: 3 point ids per boundary triangle,
   * wound so that (p1 - p0) x (p2 - p0) points OUT of the mesh. Returns false
   * (vtkErrorMacro) on bad input. Empty triangle list: no cells, true.
   */
  bool Build(const std::vector<double>& points, const std::vector<uint32_t>& triangles);

  /// The number of imaginary cells (OUT leaves) of the last Build.
  vtkIdType GetNumberOfImaginaryCells() const { return this->NumberOfImaginaryCells; }

  /**
   * (triangle index, imaginary cell): the cell lies on the outer side of that
   * triangle and shares a part of it of non-zero area. Every non-degenerate
   * triangle appears at least once (a triangle split by BSP planes may appear
   * with several cells). Sorted, without duplicates.
   */
  const std::vector<std::pair<uint32_t, uint32_t>>& GetTriangleCells() const
  {
    return this->TriangleCells;
  }

  /**
   * Two imaginary cells sharing a polygon of non-zero area on Plane (n, d,
   * |n| = 1); Cells[0] lies on the side where n.x + d < 0, Cells[1] where > 0.
   */
  struct Portal
  {
    uint32_t Cells[2];
    double Plane[4];
  };
  const std::vector<Portal>& GetPortals() const { return this->Portals; }

  /// A point inside the shared polygon of portal i (its vertex average), on the plane.
  void GetPortalCenter(vtkIdType i, double center[3]) const;

  /// The imaginary cell containing x, or -1 when x is inside the mesh (or outside the root box).
  vtkIdType FindCell(const double x[3]) const;

  /// The root box (xmin, xmax, ymin, ymax, zmin, zmax); all 0 before a Build.
  void GetRootBounds(double bounds[6]) const;

  /// Wall seconds of the last Build.
  vtkGetMacro(BuildSeconds, double);
  /// Triangle pieces stored at the BSP nodes (the triangles after the BSP splits).
  vtkGetMacro(NumberOfTrianglePieces, vtkIdType);
  /// Internal BSP nodes and the depth of the deepest one (the root has depth 1).
  vtkGetMacro(NumberOfNodes, vtkIdType);
  vtkGetMacro(MaximumDepth, vtkIdType);
  /// Triangles left out as degenerate.
  vtkGetMacro(NumberOfDegenerateTriangles, vtkIdType);
  /**
   * Pieces of triangles (of non-zero area) that reached an IN leaf on their
   * outer side: 0 for a clean closed surface; more means numerical trouble
   * or overlapping surfaces.
   */
  vtkGetMacro(NumberOfInLeafPieces, vtkIdType);
  /**
   * Non-degenerate triangles without any imaginary cell: 0 for a clean
   * surface; a triangle wholly covered by coincident triangles of the
   * opposite orientation (an internal double wall) has none.
   */
  vtkGetMacro(NumberOfTrianglesWithoutCell, vtkIdType);
  /**
   * Overlaps of coplanar pieces of opposite orientations dropped from both
   * (internal double walls: the mesh lies on both sides).
   */
  vtkGetMacro(NumberOfOverlappingPieces, vtkIdType);

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSConvexification();
  ~vtkHAVSConvexification() override;

private:
  vtkHAVSConvexification(const vtkHAVSConvexification&) = delete;
  void operator=(const vtkHAVSConvexification&) = delete;

  void Reset();
  void BuildTree();
  void BuildTriangleCells();
  void BuildPortals();

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  std::vector<std::pair<uint32_t, uint32_t>> TriangleCells;
  std::vector<Portal> Portals;
  std::vector<double> PortalCenters; // 3 per portal
  vtkIdType NumberOfImaginaryCells = 0;
  double BuildSeconds = 0.0;
  vtkIdType NumberOfTrianglePieces = 0;
  vtkIdType NumberOfNodes = 0;
  vtkIdType MaximumDepth = 0;
  vtkIdType NumberOfDegenerateTriangles = 0;
  vtkIdType NumberOfInLeafPieces = 0;
  vtkIdType NumberOfTrianglesWithoutCell = 0;
  vtkIdType NumberOfOverlappingPieces = 0;
};

VTK_ABI_NAMESPACE_END
#endif
