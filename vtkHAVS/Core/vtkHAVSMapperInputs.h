/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMapperInputs.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSMapperInputs
 * @brief   What every vtkHAVS mapper prepares from its input and volume the same way.
 *
 * The helpers vtkHAVSMapperBase calls for all three mappers (one code path,
 * one set of messages): the mesh of the mapper's input for its scalar
 * selection, the pre-integration table of the volume's property, and whether
 * the renderer can have opaque geometry in its depth buffer. Errors go out
 * through the mapper (vtkErrorWithObjectMacro); warnings that should be given
 * once go through the caller's `warnOnce` with a OnceWarning key.
 */
#ifndef vtkHAVSMapperInputs_h
#define vtkHAVSMapperInputs_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkAbstractVolumeMapper;
class vtkFloatArray;
class vtkObject;
class vtkHAVSMesh;
class vtkHAVSPreIntegrationTable;
class vtkHAVSTableResolution;
class vtkInformation;
class vtkRenderer;
class vtkVolume;

class VTKHAVSCORE_EXPORT vtkHAVSMapperInputs
{
public:
  /// The warnings a mapper gives once (keys for its warnOnce).
  enum OnceWarning
  {
    WarnShading,
    WarnGradient,
    WarnComponents,
    WarnPath,
    WarnK,
    WarnPlanes,
    WarnOrder,
    WarnBlend,
    WarnAutomaticK,
    WarnShaderProperty,
    WarnIsoSurfaces,
    WarnIsoSurfaceCells,
    WarnIsoShading,
    WarnIsoLights,
    NumberOfOnceWarnings
  };
  using WarnOnce = std::function<void(int, const std::string&)>;

  /// What PrepareMesh did.
  enum MeshState
  {
    MeshFailed,
    MeshUnchanged,
    MeshRebuilt,
    MeshScalarsUpdated ///< a new time step on the same mesh: only the scalars changed
  };
  /**
   * Builds `mesh` from the mapper's input and scalar selection when either
   * changed (progress through the mapper's UpdateProgress), reporting what
   * vtkHAVSMesh says; `mapperName` names the mapper in the messages.
   * `higherOrderSubdivision`: the tetrahedralizer's level for non-linear cells.
   */
  static MeshState PrepareMesh(vtkAbstractVolumeMapper* mapper, vtkVolume* volume,
    vtkHAVSMesh* mesh, const char* mapperName, const WarnOnce& warnOnce, int vectorMode = -1,
    int vectorComponent = 0, int higherOrderSubdivision = 0);

  /// Marks `info` as taking any vtkDataSet (the mappers split what is not
  /// tetrahedra) or a composite data set of them (appended into one grid).
  static int FillInputPortInformation(vtkInformation* info);

  /// The bounds of a composite input (its pipeline updated first); false
  /// when the input is not composite.
  static bool GetCompositeInputBounds(vtkAbstractVolumeMapper* mapper, double bounds[6]);

  /**
   * (Re)builds `table` for the volume's property when it, the scalar range,
   * the resolutions or the longest segment (the mesh's longest edge times
   * the volume matrix's largest stretch) changed; `rebuilt` says whether it did.
   * With `automatic`, the resolutions are the largest allowed and `automatic`
   * chooses the cheapest table within its error bound. `longestSegment`
   * (model units, > 0) replaces the longest edge: the level of detail's
   * long-segment table, over the bounding-box diagonal.
   */
  static bool PrepareTable(vtkAbstractVolumeMapper* mapper, vtkVolume* volume, vtkHAVSMesh* mesh,
    vtkHAVSPreIntegrationTable* table, int scalarResolution, int lengthResolution,
    const char* mapperName, const WarnOnce& warnOnce, bool* rebuilt,
    vtkHAVSTableResolution* automatic = nullptr, double longestSegment = 0.0);

  /// Warns through `mapper` unless `warned` (then sets it): a warning given once.
  static void WarnOnceBy(vtkObject* mapper, bool& warned, const std::string& message);

  /// Copies a kept float result (RGBA, `size`) into `rgba`; false when there is none.
  static bool CopyResult(const std::vector<float>* result, const int size[2], vtkFloatArray* rgba);

  /// Whether the depth buffer can hold opaque geometry when a volume is drawn:
  /// the renderer keeps an earlier depth buffer, or a visible prop other than
  /// a volume has opaque geometry.
  static bool RendererHasOpaqueGeometry(vtkRenderer* renderer);
};

VTK_ABI_NAMESPACE_END
#endif
