/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSShaderHooks.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSShaderHooks
 * @brief   The part of a volume's vtkShaderProperty that the vtkHAVS mappers apply.
 *
 * VTK users write shader replacements against the tags of
 * vtkOpenGLGPUVolumeRayCastMapper's fragment shader. Most of those tags sit
 * inside its sampling loop (`//VTK::Shading::Impl`, `//VTK::Cropping::Impl`,
 * ...), which none of the three vtkHAVS mappers has: they integrate whole
 * segments from a pre-integrated table. What they share is the last step,
 * where the volume's pixel (premultiplied RGBA) is composited over the scene,
 * and there all three honour the tags that mean the same as in VTK's ray
 * caster (HonouredTags):
 * - `//VTK::CustomUniforms::Dec`: the property's fragment custom uniforms are
 *   declared there and set every frame;
 * - `//VTK::Base::Dec`: the user's declarations (functions, uniforms);
 * - `//VTK::Base::Exit`: code run with `vec4 g_fragColor`, the volume's
 *   premultiplied colour at this pixel, before it is composited (as in VTK's
 *   `finalizeRayCast`); `gl_FragCoord` is there too.
 * Replacements are applied as VTK applies them: those marked "replace first"
 * before the mapper's own substitutions, the others after; "replace all" as
 * given. Everything else in the property (replacements of other tags or of
 * other text, vertex and geometry replacements and uniforms, whole shader
 * code) cannot be applied to these shaders: it is listed in Ignored, and the
 * mapper warns once.
 */
#ifndef vtkHAVSShaderHooks_h
#define vtkHAVSShaderHooks_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN
#include "vtkHAVSCoreModule.h"   // For export macro

#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkUniforms.h"     // For vtkUniforms (held)

#include <string> // For std::string
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkShaderProperty;

class VTKHAVSCORE_EXPORT vtkHAVSShaderHooks
{
public:
  /// One fragment replacement, as vtkShaderProperty holds it.
  struct Replacement
  {
    std::string Tag;
    std::string Code;
    bool First = true; ///< applied before the mapper's own substitutions
    bool All = false;  ///< every occurrence, not the first only
  };

  /// The tags honoured (the same for the three mappers; see the class comment).
  static const std::vector<std::string>& HonouredTags();

  /// The hooks of `property` (nullptr: none).
  static vtkHAVSShaderHooks From(vtkShaderProperty* property);

  /// The latest modification of `property` and of its custom uniforms (0 for
  /// nullptr): hooks read at this time need not be read again.
  static vtkMTimeType TimeOf(vtkShaderProperty* property);

  /// Anything to apply (a replacement or a custom uniform)?
  bool Empty() const { return this->Fragment.empty() && !this->FragmentUniforms; }

  std::vector<Replacement> Fragment;             ///< the honoured fragment replacements, in order
  vtkSmartPointer<vtkUniforms> FragmentUniforms; ///< the property's, when it has any
  std::vector<std::string> Ignored;              ///< what is not applied, one line each
  vtkMTimeType Time = 0;                         ///< TimeOf the property read
};

VTK_ABI_NAMESPACE_END
#endif
