/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVisibilityOrder.h

=========================================================================*/
/**
 * @class   vtkHAVSVisibilityOrder
 * @brief   An exact object-space face order: Williams' MPVO for HAVS.
 *
 * Plain C++, no OpenGL. Build() finds, once per mesh, the two tetrahedra of
 * every internal face of a vtkHAVSFaceSet and each face's plane (double
 * precision, from the grid's points). Sort() then, per view, orients every
 * internal face by the side of its plane the eye is on (the tetrahedron on
 * the eye's side is in front), sorts the tetrahedra topologically front to
 * back (Kahn), and emits each face when the tetrahedron behind it is visited
 * (a boundary face with its only tetrahedron: entries first, then exits).
 * For a convex mesh without visibility cycles the faces come out so that
 * the fragments along every ray arrive in depth order: k = 1 suffices up to
 * fragments at equal distance. O(faces) per view.
 *
 * Cycles (the sort stalls with tetrahedra left) are broken locally: the
 * unvisited tetrahedron with the fewest unvisited predecessors is taken next;
 * GetNumberOfCycleBreaks() counts them. Non-convex meshes get an order too,
 * but it is not exact where a ray leaves and re-enters the mesh (the
 * k-buffer absorbs what it can).
 *
 * Eye and direction of projection are given in the grid's (model)
 * coordinates; a parallel projection orients by the direction alone.
 */
#ifndef vtkHAVSVisibilityOrder_h
#define vtkHAVSVisibilityOrder_h

#include "vtkHAVSModule.h" // For export macro
#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

class vtkHAVSFaceSet;
class vtkUnstructuredGrid;

class VTKHAVS_EXPORT vtkHAVSVisibilityOrder : public vtkObject
{
public:
  static vtkHAVSVisibilityOrder* New();
  vtkTypeMacro(vtkHAVSVisibilityOrder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The adjacency of `faces` (built from `grid`, whose points are read).
   * Returns false, with an error, when a tetrahedron's face is not in the set.
   */
  bool Build(vtkHAVSFaceSet* faces, vtkUnstructuredGrid* grid);

  /**
   * The face order for a view (eye and direction in model coordinates);
   * front to back.
   */
  void Sort(const double eye[3], const double direction[3], bool parallel);

  /// Face indices, first drawn first.
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }

  /// Tetrahedra taken out of order to break visibility cycles in the last Sort().
  vtkGetMacro(NumberOfCycleBreaks, vtkIdType);

  /// Seconds the last Sort() took.
  vtkGetMacro(LastSortSeconds, double);

protected:
  vtkHAVSVisibilityOrder() = default;
  ~vtkHAVSVisibilityOrder() override = default;

private:
  vtkHAVSVisibilityOrder(const vtkHAVSVisibilityOrder&) = delete;
  void operator=(const vtkHAVSVisibilityOrder&) = delete;

  std::vector<int64_t> FaceCells;      // 2 per face: the tetrahedra (-1: none)
  std::vector<double> FacePlanes;      // 4 per face: n, d with n.x + d > 0 on FaceCells[0]'s far side
  std::vector<uint32_t> CellFaces;     // 4 per tetrahedron
  std::vector<uint32_t> Order;
  vtkIdType NumberOfCycleBreaks = 0;
  double LastSortSeconds = 0.0;
};

#endif
