/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPointGradients.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSPointGradients
 * @brief   The scalar's gradient at every point, and each tetrahedron's interpolated gradient
 * field.
 *
 * Plain C++, no OpenGL: the normals of shaded isosurfaces (issue 46: "normals
 * from interpolated vertex gradients, so surfaces look smooth as VTK's
 * contours do"). A point's gradient is the mean of its tetrahedra's (constant)
 * gradients weighted by their volumes; a degenerate tetrahedron weighs
 * nothing. Inside a tetrahedron the four points' gradients are interpolated
 * linearly (barycentric weights), so the field is affine there, G(p) = M p +
 * c, and continuous across faces: on a face it is the interpolation of the
 * face's three points' gradients, the same from both sides. A linear scalar
 * field has its exact gradient everywhere.
 *
 * The mappers that shade (the ray caster, the cell projection) read each
 * tetrahedron's field as 12 floats, three rows (M_k, c_k) with G_k(p) =
 * M_k . p + c_k (ComputeFields); the reference interpolates the points'
 * gradients at each fragment with the fragment's barycentric weights, which
 * is the same field on the face. A segment of a ray in one tetrahedron has
 * the field linear along it, so the gradient at a crossing is the mix of
 * the two ends' gradients.
 *
 * Everything in double precision; each tetrahedron's gradient in parallel
 * (vtkSMPTools), the points' sums serially (the same sums for any thread
 * count).
 */
#ifndef vtkHAVSPointGradients_h
#define vtkHAVSPointGradients_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSPointGradients
{
public:
  /// Floats per tetrahedron in ComputeFields' output: three rows (M_k, c_k).
  static constexpr int FloatsPerCell = 12;

  ///@{
  /**
   * The gradient at each point (3 doubles a point) of `scalars` (1 a point)
   * over the tetrahedra `tets` (4 point ids each) of `points` (3 a point).
   * A point of no tetrahedron, or only degenerate ones, gets 0.
   */
  static void Compute(const std::vector<float>& points, const std::vector<float>& scalars,
    const std::vector<uint32_t>& tets, std::vector<double>& gradients);
  static void Compute(const std::vector<double>& points, const std::vector<double>& scalars,
    const std::vector<uint32_t>& tets, std::vector<double>& gradients);
  ///@}

  /**
   * Each tetrahedron's interpolated field of the points' `gradients`
   * (Compute's): 12 floats, G_k(p) = fields[12 t + 4 k .. + 2] . p +
   * fields[12 t + 4 k + 3], p in `points`' frame. A degenerate tetrahedron
   * gets the mean of its points' gradients, constant.
   */
  static void ComputeFields(const std::vector<float>& points, const std::vector<uint32_t>& tets,
    const std::vector<double>& gradients, std::vector<float>& fields);

  /**
   * The points' `gradients` (3 floats a point) interpolated at `positions`
   * (3 floats a vertex, 3 vertices a triangle, in `points`' frame), each
   * triangle in the tetrahedron `cells` names (its index in `tets`), with
   * that tetrahedron's barycentric weights: the field above, as at a plane
   * section's vertices (HAVS draws a clipping plane's section as fragments;
   * vtkHAVSFramePlanes::Section). A flat tetrahedron gives its points' mean;
   * a cell out of range, 0. `out`: 3 floats a vertex.
   */
  static void InterpolateInCells(const std::vector<float>& points,
    const std::vector<uint32_t>& tets, const std::vector<float>& gradients,
    const std::vector<float>& positions, const std::vector<uint32_t>& cells,
    std::vector<float>& out);
  /// Bytes of ComputeFields' output for `tets` tetrahedra.
  static size_t FieldBytes(size_t tets) { return tets * FloatsPerCell * sizeof(float); }
};

VTK_ABI_NAMESPACE_END
#endif
