/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSShaders.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSShaders.h"

#include "vtkHAVSFrameRequest.h"
#include "vtkHAVSShaderHooks.h"

#include "vtkHAVSAdditiveLib.h"
#include "vtkHAVSCellOptics.h"
#include "vtkHAVSCellOpticsLib.h"
#include "vtkHAVSCellProjectionFS.h"
#include "vtkHAVSCellProjectionVS.h"
#include "vtkHAVSCellRecordsLib.h"
#include "vtkHAVSClearFS.h"
#include "vtkHAVSCompositeFS.h"
#include "vtkHAVSCoverageFS.h"
#include "vtkHAVSCoverageVS.h"
#include "vtkHAVSExtremumDrawFS.h"
#include "vtkHAVSExtremumResolveFS.h"
#include "vtkHAVSFaceVS.h"
#include "vtkHAVSFetchDrawFS.h"
#include "vtkHAVSInterlockDrawFS.h"
#include "vtkHAVSIntermixDepthFS.h"
#include "vtkHAVSIntermixFS.h"
#include "vtkHAVSKBufferLib.h"
#include "vtkHAVSLayerCompositeFS.h"
#include "vtkHAVSListDrawFS.h"
#include "vtkHAVSQuadVS.h"
#include "vtkHAVSRayCastFS.h"
#include "vtkHAVSRayCastPeelFS.h"
#include "vtkHAVSRayCastTileVS.h"
#include "vtkHAVSResolveFS.h"
#include "vtkHAVSSaturationMarkFS.h"
#include "vtkHAVSTableCS.h"
#include "vtkHAVSTrivialFS.h"

#include "vtkShaderProgram.h"

#include <sstream>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
/// The `//HAVS::` tag in `text` replaced by `with` (VTK's substitution of shader tags).
void Replace(std::string& text, const std::string& marker, const std::string& with)
{
  vtkShaderProgram::Substitute(text, marker, with, true);
}

/// The cell-optics library (vtkHAVSCellOpticsLib.glsl) with its code width.
std::string CellOpticsLib()
{
  return "#define HAVS_CELL_CODE_BITS " + std::to_string(vtkHAVSCellOptics::CodeBits) + "\n" +
    vtkHAVSCellOpticsLib;
}

/// A fragment-shader template with the defines and the k-buffer library in.
std::string Compose(const char* templ, int k, int pixelStride,
  const vtkHAVSShaders::Features& features = vtkHAVSShaders::Features())
{
  std::string source = templ;
  std::ostringstream defines;
  defines << "#define HAVS_K " << k << "\n#define HAVS_PIXEL_STRIDE " << pixelStride << "\n"
          << "#define HAVS_COUNT_VIOLATIONS " << (features.CountViolations ? 1 : 0) << "\n"
          << "#define HAVS_TAGGING " << (features.Tagging ? 1 : 0) << "\n"
          << "#define HAVS_OPAQUE " << (features.Opaque ? 1 : 0) << "\n"
          << "#define HAVS_CELL_SCALARS " << (features.CellScalars ? 1 : 0) << "\n"
          << "#define HAVS_CLIPPING " << (features.Clipping ? 1 : 0) << "\n"
          << "#define HAVS_PROJECTION " << features.Projection << "\n"
          << "#define HAVS_ISO " << features.IsoSurfaces << "\n"
          << "#define HAVS_ISO_SHADE " << features.IsoShade << "\n"
          << "#define HAVS_ISO_EXACT " << (features.IsoExact ? 1 : 0) << "\n";
  Replace(source, "//HAVS::Defines", defines.str());
  Replace(source, "//HAVS::KBufferLib", vtkHAVSKBufferLib);
  Replace(source, "//HAVS::CellOpticsLib", CellOpticsLib());
  return source;
}

/// A shader that integrates whole cells' segments (the cell projection's and
/// the ray caster's): no k-buffer, no violation counter, no tagging; its blend
/// and the additive blend's library in.
std::string CellSegmentShader(const char* templ, bool opaque, int blend, bool cellScalars,
  int cellBuffers, int isoSurfaces, bool isoShade, bool isoExact = true)
{
  vtkHAVSShaders::Features features;
  features.IsoExact = isoExact;
  features.IsoSurfaces = isoSurfaces;
  features.IsoShade = isoShade && isoSurfaces != 0 ? 1 : 0;
  features.CountViolations = false;
  features.Tagging = false;
  features.Opaque = opaque;
  features.CellScalars = cellScalars;
  std::string source = Compose(templ, 1, 1, features);
  Replace(source, "//HAVS::CellBlend", "#define HAVS_CELL_BLEND " + std::to_string(blend));
  Replace(source, "//HAVS::CellRecordsLib",
    "#define HAVS_CELL_BUFFERS " + std::to_string(cellBuffers) + "\n" + vtkHAVSCellRecordsLib);
  Replace(source, "//HAVS::AdditiveLib", vtkHAVSAdditiveLib);
  return source;
}

/// "E[i] = <pair i/2>.xy|zw;" for i < k.
std::string UnpackEntries(const std::string& pairPrefix, int k)
{
  std::ostringstream out;
  for (int i = 0; i < k; ++i)
  {
    out << "E[" << i << "] = " << pairPrefix << i / 2 << (i % 2 ? ".zw" : ".xy") << ";\n  ";
  }
  return out.str();
}
}

std::string vtkHAVSShaders::FaceVertexShader(bool cellScalars, bool isoShade)
{
  std::string source = vtkHAVSFaceVS;
  Replace(source, "//HAVS::Defines",
    std::string("#define HAVS_CELL_SCALARS ") + (cellScalars ? "1" : "0") +
      "\n#define HAVS_ISO_SHADE " + (isoShade ? "2" : "0") + "\n");
  return source;
}

std::string vtkHAVSShaders::QuadVertexShader()
{
  return vtkHAVSQuadVS;
}

std::string vtkHAVSShaders::IntermixShader()
{
  return vtkHAVSIntermixFS;
}

std::string vtkHAVSShaders::IntermixDepthShader()
{
  return vtkHAVSIntermixDepthFS;
}

std::string vtkHAVSShaders::LayerCompositeShader()
{
  return vtkHAVSLayerCompositeFS;
}

std::string vtkHAVSShaders::FetchDrawShader(int k, const Features& features)
{
  const int pairs = FetchAttachments(k) - 1;
  std::ostringstream declarations, store;
  declarations << "layout(location = 0) inout vec4 havsColor;\n";
  for (int a = 0; a < pairs; ++a)
  {
    declarations << "layout(location = " << a + 1 << ") inout vec4 havsEntries" << a << ";\n";
    const int second = 2 * a + 1;
    store << "havsEntries" << a << " = vec4(E[" << 2 * a << "], "
          << (second < k ? "E[" + std::to_string(second) + "]" : "vec2(HAVS_EMPTY, 0.0)")
          << ");\n  ";
  }
  std::string source = Compose(vtkHAVSFetchDrawFS, k, 1, features);
  Replace(source, "//HAVS::FetchDeclarations", declarations.str());
  Replace(source, "//HAVS::FetchLoad", UnpackEntries("havsEntries", k));
  Replace(source, "//HAVS::FetchStore", store.str());
  return source;
}

std::string vtkHAVSShaders::InterlockDrawShader(int k, InterlockKind kind, const Features& features)
{
  static const char* const extension[] = { "#extension GL_ARB_fragment_shader_interlock : require",
    "#extension GL_NV_fragment_shader_interlock : require", "" };
  static const char* const layout[] = { "layout(pixel_interlock_ordered) in;",
    "layout(pixel_interlock_ordered) in;", "" };
  static const char* const begin[] = { "beginInvocationInterlockARB();",
    "beginInvocationInterlockNV();", "" };
  static const char* const end[] = { "endInvocationInterlockARB();", "endInvocationInterlockNV();",
    "" };
  std::string source = Compose(vtkHAVSInterlockDrawFS, k, InterlockPixelStride(k), features);
  Replace(source, "//HAVS::InterlockExtension", extension[kind]);
  Replace(source, "//HAVS::InterlockLayout", layout[kind]);
  Replace(source, "//HAVS::InterlockBegin", begin[kind]);
  Replace(source, "//HAVS::InterlockEnd", end[kind]);
  return source;
}

std::string vtkHAVSShaders::SaturationMarkShader(int path, int k)
{
  std::string extension, declarations, load;
  int stride = 1;
  if (path == vtkHAVSFrameRequest::PathFramebufferFetch)
  {
    extension = "#extension GL_EXT_shader_framebuffer_fetch : require";
    declarations = "layout(location = 0) inout vec4 havsColor;\n"
                   "layout(location = 1) inout vec4 havsEntries0;";
    load = "color = havsColor;\n  front = havsEntries0.xy;";
  }
  else if (path == vtkHAVSFrameRequest::PathFragmentShaderInterlock)
  {
    stride = InterlockPixelStride(k);
    declarations = "layout(std430, binding = 0) buffer HAVSPixelEntries\n{\n"
                   "  vec4 havsPixelData[];\n};";
    load = "int base = (int(gl_FragCoord.y) * int(havsViewportSize.x) + int(gl_FragCoord.x)) *\n"
           "    HAVS_PIXEL_STRIDE;\n"
           "  color = havsPixelData[base];\n  front = havsPixelData[base + 1].xy;";
  }
  else
  {
    return std::string();
  }
  std::string source = Compose(vtkHAVSSaturationMarkFS, k, stride);
  Replace(source, "//HAVS::MarkExtension", extension);
  Replace(source, "//HAVS::MarkDeclarations", declarations);
  Replace(source, "//HAVS::MarkLoad", load);
  return source;
}

std::string vtkHAVSShaders::InterlockClearShader(int k)
{
  return Compose(vtkHAVSClearFS, k, InterlockPixelStride(k));
}

std::string vtkHAVSShaders::ListDrawShader(const Features& features)
{
  return Compose(vtkHAVSListDrawFS, 1, 1, features);
}

std::string vtkHAVSShaders::ResolveShader(int path, int k, bool groupVote, const Features& features)
{
  std::string extension, declarations, load;
  int resolveK = k;
  int stride = 1;
  switch (path)
  {
    case vtkHAVSFrameRequest::PathFramebufferFetch:
    {
      std::ostringstream d, l;
      d << "uniform sampler2D havsColorTexture;\n";
      l << "color = texelFetch(havsColorTexture, pixel, 0);\n  ";
      for (int a = 0; a + 1 < FetchAttachments(k); ++a)
      {
        d << "uniform sampler2D havsEntryTexture" << a << ";\n";
        l << "vec4 pair" << a << " = texelFetch(havsEntryTexture" << a << ", pixel, 0);\n  ";
      }
      declarations = d.str();
      load = l.str() + UnpackEntries("pair", k);
      break;
    }
    case vtkHAVSFrameRequest::PathFragmentShaderInterlock:
      stride = InterlockPixelStride(k);
      declarations =
        "layout(std430, binding = 0) buffer HAVSPixelEntries { vec4 havsPixelData[]; };\n";
      load = "int base = (pixel.y * int(havsViewportSize.x) + pixel.x) * HAVS_PIXEL_STRIDE;\n"
             "  color = havsPixelData[base];\n"
             "  for (int i = 0; i < HAVS_K; ++i)\n"
             "  {\n"
             "    vec4 pair = havsPixelData[base + 1 + i / 2];\n"
             "    E[i] = (i % 2 == 0) ? pair.xy : pair.zw;\n"
             "  }\n";
      break;
    case vtkHAVSFrameRequest::PathFragmentLists:
    {
      // A pixel's list comes out in reverse draw order: it runs back to front
      // through a k-buffer of ListResolveCapacity entries. Where group vote
      // exists, the walk goes on until no invocation of the group has nodes
      // left and every invocation loads an in-range node each turn: llvmpipe
      // (Mesa 22.3) returns wrong data for a storage-buffer load inside a loop
      // whose trip count differs between the invocations of a group
      // (measured: lists cut after one node).
      resolveK = ListResolveCapacity;
      extension = std::string(groupVote ? "#extension GL_ARB_shader_group_vote : require\n" : "") +
        "#define HAVS_BACK_TO_FRONT\n";
      declarations = "layout(r32ui, binding = 0) uniform readonly uimage2D havsListHeads;\n"
                     "layout(std430, binding = 1) readonly buffer HAVSListNodes { uvec4 "
                     "havsNodes[]; };\n"
                     "uniform int havsNodeCapacity;\n"
                     "#if HAVS_ISO_SHADE == 2\n"
                     "layout(std430, binding = 13) readonly buffer HAVSListGradients { vec4 "
                     "havsNodeGradients[]; };\n"
                     "#endif\n"
                     "HAVS_ENTRY havsListEntry(uvec4 entry, uint node)\n"
                     "{\n"
                     "  HAVS_ENTRY e = havsEntry(uintBitsToFloat(entry.x), "
                     "uintBitsToFloat(entry.y));\n"
                     "#if HAVS_ISO_SHADE == 2\n"
                     "  e.g = havsNodeGradients[node].xyz;\n"
                     "#endif\n"
                     "  return e;\n"
                     "}\n";
      std::ostringstream l;
      l << "E[0] = havsEntry(HAVS_NO_FRONT, 0.0);\n"
        << "  for (int i = 1; i < HAVS_K; ++i) { E[i] = havsEntry(HAVS_EMPTY, 0.0); }\n"
        << "  uint node = imageLoad(havsListHeads, pixel).r;\n"
        << "  for (uint n = 0u; n < uint(havsNodeCapacity); ++n)\n"
        << "  {\n"
        << "    bool walking = node < uint(havsNodeCapacity);\n"
        << (groupVote ? "    if (!anyInvocationARB(walking)) { break; }\n"
                      : "    if (!walking) { break; }\n")
        << "    uvec4 entry = havsNodes[walking ? node : 0u];\n"
        << "    if (walking)\n"
        << "    {\n"
        << "      havsInsertBackToFront(color, E, havsListEntry(entry, node), opaqueDistance);\n"
        << "      node = entry.z;\n"
        << "    }\n"
        << "  }\n";
      load = l.str();
      break;
    }
    default:
      return std::string();
  }
  std::string source = vtkHAVSResolveFS;
  Replace(source, "//HAVS::ResolveExtension", extension);
  Replace(source, "//HAVS::ResolveDeclarations", declarations);
  Replace(source, "//HAVS::ResolveLoad", load);
  return Compose(source.c_str(), resolveK, stride, features);
}

std::string vtkHAVSShaders::ExtremumDrawShader(const Features& features)
{
  return Compose(vtkHAVSExtremumDrawFS, 1, 1, features);
}

std::string vtkHAVSShaders::ExtremumResolveShader(bool cellScalars)
{
  std::string source = vtkHAVSExtremumResolveFS;
  Replace(source, "//HAVS::Defines",
    std::string("#define HAVS_CELL_SCALARS ") + (cellScalars ? "1" : "0") + "\n");
  Replace(source, "//HAVS::CellOpticsLib", CellOpticsLib());
  return source;
}

std::string vtkHAVSShaders::TrivialShader()
{
  return vtkHAVSTrivialFS;
}

std::string vtkHAVSShaders::CoverageVertexShader()
{
  return vtkHAVSCoverageVS;
}

std::string vtkHAVSShaders::CoverageShader()
{
  return vtkHAVSCoverageFS;
}

std::string vtkHAVSShaders::TableComputeShader(int cells, int local)
{
  std::string source = vtkHAVSTableCS;
  Replace(source, "//HAVS::Defines",
    "#define HAVS_CELLS " + std::to_string(cells) + "\n#define HAVS_LOCAL " +
      std::to_string(local));
  return source;
}

std::string vtkHAVSShaders::CompositeShader(
  const vtkHAVSShaderHooks* hooks, const std::string& uniformDeclarations)
{
  std::string source = vtkHAVSCompositeFS;
  if (!hooks)
  {
    return source;
  }
  // As VTK applies a shader property: the user's "replace first" replacements,
  // the mapper's own substitutions (the custom uniforms' declarations), the rest.
  for (bool first : { true, false })
  {
    if (!first)
    {
      Replace(source, "//VTK::CustomUniforms::Dec", uniformDeclarations);
    }
    for (const vtkHAVSShaderHooks::Replacement& r : hooks->Fragment)
    {
      if (r.First == first)
      {
        vtkShaderProgram::Substitute(source, r.Tag, r.Code, r.All);
      }
    }
  }
  return source;
}

std::string vtkHAVSShaders::CellProjectionVertexShader()
{
  return vtkHAVSCellProjectionVS;
}

std::string vtkHAVSShaders::CellProjectionShader(bool opaque, int blend, bool cellScalars,
  int cellBuffers, int isoSurfaces, bool isoShade, bool isoExact)
{
  return CellSegmentShader(vtkHAVSCellProjectionFS, opaque, blend, cellScalars, cellBuffers,
    isoSurfaces, isoShade, isoExact);
}

std::string vtkHAVSShaders::RayCastPeelShader()
{
  Features features;
  features.CountViolations = false;
  features.Tagging = false;
  features.Opaque = false;
  return Compose(vtkHAVSRayCastPeelFS, 1, 1, features);
}

std::string vtkHAVSShaders::RayCastShader(
  bool opaque, int blend, bool cellScalars, int cellBuffers, int isoSurfaces, bool isoShade)
{
  return CellSegmentShader(
    vtkHAVSRayCastFS, opaque, blend, cellScalars, cellBuffers, isoSurfaces, isoShade);
}

std::string vtkHAVSShaders::RayCastTileVertexShader()
{
  return vtkHAVSRayCastTileVS;
}

VTK_ABI_NAMESPACE_END
