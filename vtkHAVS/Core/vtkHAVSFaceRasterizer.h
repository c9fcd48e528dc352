/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceRasterizer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFaceRasterizer
 * @brief   Exact software rasterization of triangles at the pixel centres.
 *
 * Plain C++, no OpenGL, double precision. Every pixel's ray (through the
 * pixel's centre, from the eye, or along the direction of projection from the
 * near plane) is tested against every triangle whose screen box covers the
 * pixel with a watertight ray-triangle test (Woop, Benthin and Wald 2013),
 * ties on shared edges and vertices broken by a symbolic perturbation, so a
 * ray through an edge or a vertex of a closed surface hits exactly one of the
 * triangles there. The hits of each pixel come out sorted by distance along
 * the ray (ties by triangle index). The triangles are binned to 32 x 32 pixel
 * tiles, and each tile computes its pixels' rays once (the rays cost as much
 * as the tests when recomputed per triangle).
 *
 * Used by the exact reference (vtkHAVSReferenceRenderer: every face of the
 * mesh, world coordinates) and by the exact order's boundary layers
 * (vtkHAVSVisibilityOrder: the boundary faces, the grid's coordinates). The
 * points may be in any frame; SetView() takes that frame's projection to clip
 * coordinates, and the eye and the direction of projection in it.
 */
#ifndef vtkHAVSFaceRasterizer_h
#define vtkHAVSFaceRasterizer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"

#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSFaceRasterizer : public vtkObject
{
public:
  static vtkHAVSFaceRasterizer* New();
  vtkTypeMacro(vtkHAVSFaceRasterizer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The view: the points' frame to clip coordinates (row-major 4x4), the eye
   * and the direction of projection in the points' frame, the projection, the
   * image size in pixels.
   */
  void SetView(const double pointsToClip[16], const double eye[3], const double direction[3],
    bool parallel, int width, int height);
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /// A pixel's ray: origin, unit direction, and the distance of the origin
  /// from the eye along the ray's measure (0 in perspective).
  struct Ray
  {
    double Origin[3];
    double Direction[3];
    double Offset;
  };
  Ray GetPixelRay(int i, int j) const;

  /// Clip coordinates (x, y, z in [-1, 1]) back to the points' frame.
  void Unproject(double x, double y, double z, double out[3]) const;

  /// One hit of a pixel's ray with a triangle.
  struct Hit
  {
    double Distance;   ///< Offset + distance along the ray
    double Weights[3]; ///< barycentric weights of the triangle's three points
    uint32_t Triangle; ///< index in the list given to Rasterize()
    bool FrontFacing;  ///< the ray sees the counter-clockwise side
  };

  /**
   * Rasterizes triangles (3 point ids each into `points`, 3 doubles per
   * point): afterwards pixel p's hits are GetHits()[GetPixelStart()[p] …
   * GetPixelStart()[p + 1]), nearest first. `skip` (optional) leaves a
   * triangle out. Runs in parallel (vtkSMPTools); the result does not depend
   * on the thread count.
   */
  void Rasterize(const std::vector<double>& points, const uint32_t* triangles,
    vtkIdType numberOfTriangles, const std::function<bool(vtkIdType)>& skip = nullptr);

  const std::vector<vtkIdType>& GetPixelStart() const { return this->PixelStart; }
  const std::vector<Hit>& GetHits() const { return this->Hits; }
  /// Frees the hits (the view is kept).
  void ReleaseHits();

protected:
  vtkHAVSFaceRasterizer() = default;
  ~vtkHAVSFaceRasterizer() override = default;

private:
  vtkHAVSFaceRasterizer(const vtkHAVSFaceRasterizer&) = delete;
  void operator=(const vtkHAVSFaceRasterizer&) = delete;

  /// Pixel-centre coordinates (x, y) of a point; false behind the eye.
  bool Project(const double p[3], double& px, double& py) const;
  /// The pixels a triangle may cover (x0, x1, y0, y1, inclusive, one pixel of
  /// margin; the whole image when a point lies behind the eye); false when
  /// none.
  bool ScreenBox(const double* v[3], int box[4]) const;

  double PointsToClip[16];
  double ClipToPoints[16];
  double Eye[3] = { 0, 0, 0 };
  double Direction[3] = { 0, 0, 1 };
  bool Parallel = false;
  int Width = 0;
  int Height = 0;
  std::vector<vtkIdType> PixelStart;
  std::vector<Hit> Hits;
};

VTK_ABI_NAMESPACE_END
#endif
