/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSViewFrame.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSViewFrame
 * @brief   Every coordinate frame of one view, computed once, in double.
 *
 * Plain C++, no OpenGL. A frame of vtkHAVSVolumeMapper sees the mesh in
 * several coordinate systems; they are all made here, once per frame, from
 * the renderer's camera, its tiled viewport and the volume's matrix:
 *
 * - grid: the input's own coordinates (the exact orders work there);
 * - model: grid minus the mesh's shift (the bounds' centre), what the GPU
 *   gets as floats, so that huge coordinates keep their precision;
 * - world: after the volume's matrix; eye-relative world (world minus the eye
 *   position), where the fragment shaders measure distances;
 * - clip: after the camera's composite projection for the viewport's aspect.
 *
 * The eye of a parallel camera: a parallel view measures distances along the
 * direction of projection only, and where the camera stands on its axis
 * changes nothing but those distances' offset. The frame's eye is therefore
 * moved along the axis to one bounds diagonal in front of the volume's centre
 * when the camera stands farther (the clipping range moved with it): the
 * camera's own position may be a hundred diagonals away, and float distances
 * measured from there lose the digits that order a ray's nearly coincident
 * fragments (a ray grazing a silhouette edge enters and leaves the mesh
 * within 1e-5 of a diagonal).
 *
 * Matrices are row-major (vtkMatrix4x4's element order); ToColumnMajor()
 * gives OpenGL's.
 */
#ifndef vtkHAVSViewFrame_h
#define vtkHAVSViewFrame_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

VTK_ABI_NAMESPACE_BEGIN

class vtkRenderer;
class vtkVolume;

class VTKHAVSCORE_EXPORT vtkHAVSViewFrame
{
public:
  /**
   * The frame of `renderer`'s active camera and tiled viewport for `volume`,
   * with the mesh shifted by `shift` (model = grid - shift). `imageScale` in
   * (0, 1]: the image is drawn at that scale of the viewport along each axis
   * (the level of detail's reduced image; Width and Height then the drawn
   * size, at least 1, FullWidth and FullHeight the viewport's). The
   * projection stays the viewport's: the drawn image covers the viewport.
   */
  static vtkHAVSViewFrame Make(
    vtkRenderer* renderer, vtkVolume* volume, const double shift[3], double imageScale = 1.0);

  double ModelToEyeRelative[16]; ///< model -> world - eye
  double ModelToClip[16];        ///< model -> clip
  double ClipToEyeRelative[16];  ///< clip -> world - eye
  double GridToWorld[16];        ///< the volume's matrix
  double GridToClip[16];         ///< grid -> clip

  double EyeWorld[3] = { 0, 0, 0 };       ///< parallel: on the axis, near the volume (above)
  double DirectionWorld[3] = { 0, 0, 1 }; ///< direction of projection, unit
  double EyeGrid[3] = { 0, 0, 0 };
  double DirectionGrid[3] = { 0, 0, 1 }; ///< not normalized (the matrix may scale)
  double ClippingRange[2] = { 0, 1 };    ///< from EyeWorld
  bool Parallel = false;
  bool FlipFacing = false; ///< the volume's matrix mirrors (negative determinant)

  int Width = 0; ///< the image drawn: the renderer's tiled viewport times the image scale
  int Height = 0;
  int FullWidth = 0; ///< the renderer's tiled viewport
  int FullHeight = 0;
  int OriginX = 0;
  int OriginY = 0;

  /// Whether the viewport has pixels.
  bool HasPixels() const { return this->Width > 0 && this->Height > 0; }
  /// Whether the image is drawn at less than the viewport's size.
  bool IsReduced() const
  {
    return this->Width != this->FullWidth || this->Height != this->FullHeight;
  }

  /// A row-major double matrix as OpenGL's column-major floats.
  static void ToColumnMajor(const double rowMajor[16], float columnMajor[16]);
};

VTK_ABI_NAMESPACE_END
#endif
