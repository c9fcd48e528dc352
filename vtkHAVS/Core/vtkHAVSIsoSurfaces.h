/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSIsoSurfaces.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSIsoSurfaces
 * @brief   The isosurfaces a frame draws: values, colours, and how a segment crosses them.
 *
 * Plain C++, no OpenGL. vtkVolumeMapper's isosurface blend
 * (ISOSURFACE_BLEND, 5; the values are the volume property's
 * GetIsoSurfaceValues()) with VTK's semantics: where a ray crosses an
 * isovalue the surface takes the transfer functions' colour and opacity at
 * that value, and nothing contributes between the surfaces. The project's
 * mixed mode (vtkHAVSMapperBase::IsoSurfacesInComposite, the thesis'
 * isosurfaces inside a volume) composites the same surfaces into the
 * composite blend's volume: the segments are split at them.
 *
 * The scalar is linear along a segment in a tetrahedron, so a crossing is
 * found exactly: a segment from scalar sf to sb crosses v when v lies in
 * [sf, sb) (rising) or (sb, sf] (falling), the half-open interval counting a
 * crossing at a shared face once, in the segment behind it; several are
 * crossed in the order the ray meets them. The mappers' shaders
 * (vtkHAVSKBufferLib's havsSegment) and the exact reference
 * (vtkHAVSReferenceRenderer) follow this rule.
 */
#ifndef vtkHAVSIsoSurfaces_h
#define vtkHAVSIsoSurfaces_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkVolumeProperty;

class VTKHAVSCORE_EXPORT vtkHAVSIsoSurfaces
{
public:
  /// The most isovalues a frame draws (the shaders' uniform arrays).
  static constexpr int MaximumCount = 8;
  /// vtkVolumeMapper::ISOSURFACE_BLEND.
  static constexpr int IsoSurfaceBlend = 5;

  /**
   * The surfaces of `blendMode` for `property` (component 0): the property's
   * isovalues under the isosurface blend, or under the composite blend with
   * `inComposite`; none otherwise. Values outside `scalarRange` (never
   * crossed) and repeated values are left out, the rest sorted; beyond
   * MaximumCount they are counted in Dropped.
   */
  static vtkHAVSIsoSurfaces Make(
    vtkVolumeProperty* property, int blendMode, bool inComposite, const double scalarRange[2]);

  /// The premultiplied colour and opacity of the surface at data value v.
  static void SurfaceColor(vtkVolumeProperty* property, double v, double rgba[4]);

  /**
   * The isovalues (indices into Values) a segment from sf to sb crosses, in
   * the order the ray meets them (the rule above).
   */
  std::vector<int> Crossed(double sf, double sb) const;

  /**
   * What the shaders compile in for `blendMode` (HAVS_ISO): 0 nothing (a
   * composite frame pays nothing for the isosurfaces), 1 the isosurface
   * blend, 2 the mixed mode with surfaces to draw.
   */
  int ShaderMode(int blendMode) const
  {
    return blendMode == IsoSurfaceBlend ? 1 : (this->Composite && this->Count > 0 ? 2 : 0);
  }

  int Count = 0;                       ///< surfaces drawn (0: none)
  bool Composite = false;              ///< the volume between them too (the mixed mode)
  int Dropped = 0;                     ///< isovalues beyond MaximumCount, left out
  double Values[MaximumCount] = {};    ///< data values, ascending
  float Normalized[MaximumCount] = {}; ///< in the scalar range's [0, 1] (the shaders' scalars)
  double Colors[MaximumCount][4] = {}; ///< premultiplied (rgb a, a): SurfaceColor at Values
};

VTK_ABI_NAMESPACE_END
#endif
