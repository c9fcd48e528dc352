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
 * Matrices are row-major (vtkMatrix4x4's element order); ToColumnMajor()
 * gives OpenGL's.
 */
#ifndef vtkHAVSViewFrame_h
#define vtkHAVSViewFrame_h

#include "vtkHAVSCoreModule.h" // For export macro

class vtkRenderer;
class vtkVolume;

class VTKHAVSCORE_EXPORT vtkHAVSViewFrame
{
public:
  /**
   * The frame of `renderer`'s active camera and tiled viewport for `volume`,
   * with the mesh shifted by `shift` (model = grid - shift).
   */
  static vtkHAVSViewFrame Make(vtkRenderer* renderer, vtkVolume* volume, const double shift[3]);

  double ModelToEyeRelative[16]; ///< model -> world - eye
  double ModelToClip[16];        ///< model -> clip
  double ClipToEyeRelative[16];  ///< clip -> world - eye
  double GridToWorld[16];        ///< the volume's matrix
  double GridToClip[16];         ///< grid -> clip

  double EyeWorld[3] = { 0, 0, 0 };
  double DirectionWorld[3] = { 0, 0, 1 }; ///< direction of projection, unit
  double EyeGrid[3] = { 0, 0, 0 };
  double DirectionGrid[3] = { 0, 0, 1 }; ///< not normalized (the matrix may scale)
  double ClippingRange[2] = { 0, 1 };
  bool Parallel = false;
  bool FlipFacing = false; ///< the volume's matrix mirrors (negative determinant)

  int Width = 0; ///< the renderer's tiled viewport
  int Height = 0;
  int OriginX = 0;
  int OriginY = 0;

  /// Whether the viewport has pixels.
  bool HasPixels() const { return this->Width > 0 && this->Height > 0; }

  /// A row-major double matrix as OpenGL's column-major floats.
  static void ToColumnMajor(const double rowMajor[16], float columnMajor[16]);
};

#endif
