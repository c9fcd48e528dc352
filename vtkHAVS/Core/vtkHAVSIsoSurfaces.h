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
 *
 * Shading (the property's ShadeOn, MakeShading): each crossing's colour lit
 * by the renderer's lights with the normal of the interpolated point
 * gradients there (vtkHAVSPointGradients), Phong's model as VTK's volume
 * mappers light (Shade): ambient k_a c, per light diffuse k_d (n.l) c L_d and
 * specular k_s (r.v)^p L_s, the normal turned towards the eye (two-sided),
 * the colour clamped to [0, 1], the opacity unchanged. Lights are
 * directional (a positional light shines from its position towards its focal
 * point, with no cone or attenuation: counted in PositionalLights). The
 * shaders (vtkHAVSKBufferLib's havsShadeSurface) compute the same in float.
 */
#ifndef vtkHAVSIsoSurfaces_h
#define vtkHAVSIsoSurfaces_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkLightCollection;
class vtkMatrix4x4;
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

  /// The most lights the shading takes (the shaders' uniform arrays).
  static constexpr int MaximumLights = 8;

  /**
   * The shading of these surfaces for `property`'s `component`: Shaded when
   * the property's Shade is on and there are surfaces; the lights of
   * `lights` that are on (world directions towards them; nullptr or none on:
   * ambient only); NormalMatrix the inverse transpose of `volumeMatrix`'s
   * linear part (model gradients to world normals; nullptr: identity).
   */
  void MakeShading(vtkVolumeProperty* property, int component, vtkLightCollection* lights,
    vtkMatrix4x4* volumeMatrix);

  /**
   * The shaded colour of a surface of premultiplied colour `rgba` where the
   * world gradient is `gradient`, seen from direction `toEye` (unit, from
   * the surface towards the eye): the model above. A zero or non-finite
   * gradient leaves `rgba` unshaded.
   */
  void Shade(
    const double rgba[4], const double gradient[3], const double toEye[3], double out[4]) const;

  /// One light: world direction towards it (unit), its colours times its intensity.
  struct Light
  {
    double Direction[3];
    double Diffuse[3];
    double Specular[3];
  };

  int Count = 0;                       ///< surfaces drawn (0: none)
  bool Composite = false;              ///< the volume between them too (the mixed mode)
  int Dropped = 0;                     ///< isovalues beyond MaximumCount, left out
  double Values[MaximumCount] = {};    ///< data values, ascending
  float Normalized[MaximumCount] = {}; ///< in the scalar range's [0, 1] (the shaders' scalars)
  double Colors[MaximumCount][4] = {}; ///< premultiplied (rgb a, a): SurfaceColor at Values

  bool Shaded = false;        ///< the surfaces are lit (MakeShading)
  double Ambient = 0.0;       ///< the property's k_a
  double Diffuse = 0.0;       ///< k_d
  double Specular = 0.0;      ///< k_s
  double SpecularPower = 1.0; ///< p
  int LightCount = 0;         ///< lights taken
  int DroppedLights = 0;      ///< lights on beyond MaximumLights, left out
  int PositionalLights = 0;   ///< positional lights taken as directional
  Light Lights[MaximumLights] = {};
  double NormalMatrix[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }; ///< row-major
};

VTK_ABI_NAMESPACE_END
#endif
