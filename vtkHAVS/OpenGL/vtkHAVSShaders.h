/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSShaders.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSShaders
 * @brief   The GLSL sources of every vtkHAVS pass, generated for a k and a path.
 *
 * The templates are the `.glsl` files of vtkHAVS/shaders, embedded at build
 * time; `//HAVS::` tags in them are substituted here, as VTK's own mappers
 * compose their shaders (vtkShaderProgram::Substitute on named tags): the
 * defines (HAVS_K, the per-pixel stride), the shared k-buffer library, the
 * per-path declarations and loads. All three mappers' programs are made here:
 * HAVS's k-buffer passes, the cell projection's and the ray caster's. No OpenGL: the sources can be
 * generated and checked (e.g. by glslangValidator) on a machine without the matching GPU.
 */
#ifndef vtkHAVSShaders_h
#define vtkHAVSShaders_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSOpenGLModule.h" // For export macro

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSShaderHooks;

/**
 * What a k-buffer shader does per fragment besides the k-buffer itself;
 * each feature left out is compiled out (no cost where a frame does not
 * need it).
 */
struct vtkHAVSKBufferShaderFeatures
{
  bool CountViolations = true; ///< the order-violation counter and its tie tolerance (fwidth)
  bool Tagging = true;         ///< boundary fragments carry their role (a per-fragment fetch)
  bool Opaque = true;          ///< opaque geometry may end the rays (a per-fragment depth fetch)
  bool CellScalars = false;    ///< a fragment carries the scalar of the cell behind it
  bool Clipping = true;        ///< clipping or near planes cut the mesh (a loop over them)
  int Projection = -1;         ///< 0 perspective, 1 parallel, -1 per frame (a uniform)
  int IsoSurfaces = 0; ///< 0 none, 1 the isosurface blend, 2 the mixed mode (vtkHAVSIsoSurfaces)
  /// The isosurfaces lit (HAVS_ISO_SHADE): 0 no, 1 by the cells' gradient
  /// fields (the cell mappers), 2 by the gradients the entries carry (HAVS's
  /// fragment lists).
  int IsoShade = 0;
  /// Isosurface crossings on the pixel's exact ray in double (HAVS_ISO_EXACT:
  /// HAVS's havsOnFace, the cell projection's face scalars); false only for
  /// the testing controls (the float path as the rasterizer gives it).
  bool IsoExact = true;
};

class VTKHAVSOPENGL_EXPORT vtkHAVSShaders
{
public:
  ///@{
  /// The largest k of each path: framebuffer fetch (1 + (k+1)/2 <= 8 colour
  /// attachments), interlock (per-pixel storage); the fragment-list resolve
  /// sorts up to ListResolveCapacity fragments per pixel exactly.
  static constexpr int MaximumFetchK = 14;
  static constexpr int MaximumInterlockK = 64;
  static constexpr int ListResolveCapacity = 64;
  ///@}

  /// What a k-buffer shader compiles in (vtkHAVSKBufferShaderFeatures).
  using Features = vtkHAVSKBufferShaderFeatures;

  /// Vertex shader of the passes that rasterize the faces (point or cell scalars).
  static std::string FaceVertexShader(bool cellScalars = false, bool isoShade = false);
  /// Vertex shader of the full-viewport passes.
  static std::string QuadVertexShader();

  /// Framebuffer-fetch draw pass: entries in 1 + (k+1)/2 colour attachments.
  static std::string FetchDrawShader(int k, const Features& features = Features());
  /// How the interlock draw pass guards its read-modify-write.
  enum InterlockKind
  {
    InterlockARB,  ///< ARB_fragment_shader_interlock, ordered
    InterlockNV,   ///< NV_fragment_shader_interlock, ordered
    InterlockNone, ///< none: only for a rasterizer that shades a pixel's
                   ///< fragments one at a time in primitive order (llvmpipe),
                   ///< to test the path's storage layout, clear and resolve
  };
  /// Interlock draw pass.
  static std::string InterlockDrawShader(
    int k, InterlockKind kind, const Features& features = Features());
  /// Saturation mark between batches of the face draw (vtkHAVSGLSaturationMask)
  /// on the framebuffer-fetch and interlock paths; empty for other paths.
  static std::string SaturationMarkShader(int path, int k);
  /// Interlock clear pass (per-pixel storage to empty).
  static std::string InterlockClearShader(int k);
  /// Fragment-list draw pass (append to per-pixel lists).
  static std::string ListDrawShader(const Features& features = Features());

  /// Resolve (flush) pass of a path (vtkHAVSVolumeMapper::KBufferPaths);
  /// `groupVote`: the fragment-list walk uses ARB_shader_group_vote.
  static std::string ResolveShader(
    int path, int k, bool groupVote, const Features& features = Features());
  /// Number of storage slots (vec4) per pixel on the interlock path.
  static int InterlockPixelStride(int k) { return 1 + (k + 1) / 2; }
  /// Colour attachments of the framebuffer-fetch path.
  static int FetchAttachments(int k) { return 1 + (k + 1) / 2; }

  /// Maximum / minimum intensity passes.
  static std::string ExtremumDrawShader(const Features& features = Features());
  /// (`cellScalars`: the result is a cell code, coloured from the cell optics.)
  static std::string ExtremumResolveShader(bool cellScalars = false);

  /// Benchmark aid: a trivial fragment shader (rasterization cost alone).
  static std::string TrivialShader();

  /// Translucent layers intermixed with the volume (vtkHAVSIntermixPass):
  /// the per-slab sum, a layer's depth as the slab's cut, a layer composited
  /// over the window.
  static std::string IntermixShader();
  static std::string IntermixDepthShader();
  static std::string LayerCompositeShader();
  /// Composites the result over VTK's framebuffer; with the volume's shader
  /// property's `hooks` applied (vtkHAVSShaderHooks), its custom uniforms
  /// declared by `uniformDeclarations` (vtkOpenGLUniforms::GetDeclarations).
  static std::string CompositeShader(
    const vtkHAVSShaderHooks* hooks = nullptr, const std::string& uniformDeclarations = "");
  ///@{
  /// The level of detail's coverage mask (vtkHAVSGLFrameTargets::SetCoverage):
  /// the boundary faces' positions, marked where they lie before the opaque depth.
  static std::string CoverageVertexShader();
  static std::string CoverageShader();
  ///@}
  /// The pre-integrated table's compute shader (vtkHAVSGLTableBuilder): `cells`
  /// = NS - 1 table intervals (1 to 1023), work groups of `local` threads.
  static std::string TableComputeShader(int cells, int local);
  ///@{
  /// vtkHAVSCellProjectionMapper: the faces' vertex shader, and the fragment
  /// shader (the k-buffer library's segment look-up; the opaque cut compiled
  /// in with `opaque`; `blend`: vtkHAVSCellProjectionMapper's blend mode:
  /// composite, maximum, minimum or additive; `cellScalars`: the cells'
  /// fields are cell codes, their segments read the cell optics;
  /// `cellBuffers`: the storage buffers the cell records lie in,
  /// vtkHAVSGLCellRecords; `isoSurfaces`: Features::IsoSurfaces; `isoShade`:
  /// Features::IsoShade; `isoExact`: Features::IsoExact).
  static std::string CellProjectionVertexShader();
  static std::string CellProjectionShader(bool opaque, int blend = 0, bool cellScalars = false,
    int cellBuffers = 1, int isoSurfaces = 0, bool isoShade = false, bool isoExact = true);
  ///@}

  ///@{
  /// vtkHAVSRayCastMapper: the boundary entries' depth-peeling fragment
  /// shader (with CellProjectionVertexShader), and the ray-casting pass's
  /// (with RayCastTileVertexShader; the opaque cut compiled in with
  /// `opaque`; `blend`, `cellScalars`, `cellBuffers`, `isoSurfaces` and
  /// `isoShade` as CellProjectionShader's).
  static std::string RayCastPeelShader();
  static std::string RayCastShader(bool opaque, int blend = 0, bool cellScalars = false,
    int cellBuffers = 1, int isoSurfaces = 0, bool isoShade = false);
  /// The ray-casting pass's vertex shader: one instance per screen tile.
  static std::string RayCastTileVertexShader();
  ///@}
};

VTK_ABI_NAMESPACE_END
#endif
