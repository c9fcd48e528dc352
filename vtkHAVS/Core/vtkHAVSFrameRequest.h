/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFrameRequest.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSFrameRequest.h
 * @brief What vtkHAVSVolumeMapper asks its graphics layer to draw in one
 * frame, and what the layer reports back.
 *
 * The request carries the frame's settings and inputs; each input carries a
 * version (a modification time) so that the GPU objects upload only what
 * changed. The graphics layer's passes (vtkHAVSGLPassContext, the k-buffers,
 * the extremum and raster-bound passes) include this header, not the
 * mapper's public one. Plain structs: not wrapped.
 */
#ifndef vtkHAVSFrameRequest_h
#define vtkHAVSFrameRequest_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkType.h" // For vtkIdType, vtkMTimeType

#include <cstdint> // For uint32_t, uint8_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFramePlanes;
class vtkHAVSMesh;
class vtkHAVSPreIntegrationTable;
class vtkHAVSViewFrame;

/// What the graphics layer draws: one frame's settings and inputs.
struct vtkHAVSFrameRequest
{
  /// The k-buffer paths (vtkHAVSVolumeMapper::KBufferPaths has these values).
  enum Paths
  {
    PathAutomatic = 0,
    PathFramebufferFetch = 1,
    PathFragmentShaderInterlock = 2,
    PathFragmentLists = 3
  };
  /// "Automatic", "FramebufferFetch", "FragmentShaderInterlock", "FragmentLists"; "None" else.
  static const char* GetPathName(int path)
  {
    switch (path)
    {
      case PathAutomatic:
        return "Automatic";
      case PathFramebufferFetch:
        return "FramebufferFetch";
      case PathFragmentShaderInterlock:
        return "FragmentShaderInterlock";
      case PathFragmentLists:
        return "FragmentLists";
      default:
        return "None";
    }
  }
  /// The blend modes HAVS draws (vtkVolumeMapper's values).
  enum Blends
  {
    CompositeBlend = 0,
    MaximumIntensityBlend = 1,
    MinimumIntensityBlend = 2
  };

  const vtkHAVSViewFrame* View = nullptr;
  vtkHAVSMesh* Mesh = nullptr;                 ///< points, scalars (GetBuildTime())
  vtkHAVSPreIntegrationTable* Table = nullptr; ///< the table (TableVersion)
  vtkMTimeType TableVersion = 0;
  const std::vector<uint32_t>* DrawTriangles = nullptr; ///< faces in draw order
  const std::vector<uint8_t>* DrawBoundary = nullptr;
  vtkMTimeType DrawOrderVersion = 0;
  vtkHAVSFramePlanes* Planes = nullptr; ///< planes and sections (GetSectionsVersion())
  int Path = 0;                         ///< Paths
  int K = 1;
  int BlendMode = CompositeBlend;
  float TerminationOpacity = 1.0f;
  bool Tagging = true;      ///< boundary fragments carry their entry/exit role
  bool CellScalars = false; ///< the scalars are the cells' (vtkHAVSMesh::HasCellScalars)
  int IsoSurfaces = 0; ///< vtkHAVSIsoSurfaces::ShaderMode: 0 none, 1 the blend, 2 the mixed mode
  /// The isosurfaces lit (the fragment-list path only): each vertex carries its point's
  /// gradient (PointGradients, 3 floats a point, model coordinates; its version).
  bool IsoShade = false;
  /// Isosurface fragments placed on the pixel's exact ray (the shaders'
  /// HAVS_ISO_EXACT; false only for NoFaceClampForTesting).
  bool IsoExact = true;
  const std::vector<float>* PointGradients = nullptr;
  vtkMTimeType PointGradientsVersion = 0;
  bool Opaque = true;        ///< opaque geometry may be in the depth buffer (rays end there)
  float GapLength = 3.0e38f; ///< segments longer than this contribute nothing (3e38: off)
  bool Composite = true;     ///< composite the result over the window (else keep it)
  bool CountViolations = true;
  bool RasterBoundOnly = false;
  bool MeasureStages = false;
  bool KeepResult = false;
  bool Finish = false;        ///< wait for the draw to finish (the frame time is measured)
  bool SkipSaturated = false; ///< reject saturated pixels' fragments early (SkipSaturatedPixels)
};

/// What the graphics layer reports of a drawn frame.
struct vtkHAVSFrameResult
{
  vtkIdType Violations = 0;
  std::vector<int> ViolationPixels;
  vtkIdType Fragments = 0;
  vtkIdType SaturatedPixels = -1; ///< marked by the last saturation pass (-1: not read)
  vtkIdType ShadedFragments = -1; ///< fragment-shader invocations of the face draw (-1: not read)
  bool OpaqueDepthMultisampled = false; ///< the opaque depth came from a multisampled framebuffer
  bool OpaqueDepthCaptured = false;     ///< the opaque depth was read (resolved if multisampled)
  double UploadSeconds = 0.0;
  double DrawSeconds = 0.0;
  double FlushSeconds = 0.0;
  double CompositeSeconds = 0.0;
  double ReadbackSeconds = 0.0;
  bool GeometryUploaded = false; ///< the mesh's points and scalars went to the GPU
  bool ScalarsUploaded = false;  ///< its scalars only (a new time step)
  bool OrderUploaded = false;    ///< the face order
  bool TableUploaded = false;    ///< the pre-integration table
};

VTK_ABI_NAMESPACE_END
#endif
// VTK-HeaderTest-Exclude: vtkHAVSFrameRequest.h
