/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSReferenceRenderer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSReferenceRenderer
 * @brief   The exact image of a tetrahedral grid: the yardstick of vtkHAVS.
 *
 * Plain C++, no OpenGL. The optical model of Williams and Max 1992 (as VTK's
 * unstructured-grid integrators), integrated exactly. One ray per pixel centre, exactly as VTK's
 * camera maps pixels (the inverse of its composite projection, perspective or parallel). Every
 * ray–face intersection is found in double precision with a watertight test (Woop, Benthin and Wald
 * 2013: per ray, every vertex is sheared once into the ray's frame, so edge functions of shared
 * edges are exactly opposite) and a consistent tie-break (simulation of simplicity: an edge
 * function that is exactly 0 takes the sign the ray would see if moved by (e, e^2) in its frame),
 * so a ray through a shared edge or vertex is neither missed nor counted twice. Faces are found per
 * ray through their screen bounding boxes (a face-driven traversal, parallel over faces with
 * vtkSMPTools).
 *
 * Along each ray the hits are sorted; whether a segment lies in the mesh
 * follows from the parity of the boundary hits before it (a pair of
 * boundary hits at the same distance — a ray grazing an edge — leaves it
 * unchanged), so holes, cavities and separate parts are empty space. Each
 * segment is integrated under the optical model of MISSION.md (scalar linear
 * along it, colour and opacity from the property's own functions), split at
 * the transfer-function nodes, each piece adaptively to 1e-6
 * (vtkHAVSPreIntegrationTable::IntegrateSegment).
 *
 * Rays start at the camera's near plane and are cut by the clipping planes
 * (SetClippingPlanes, world coordinates, the normal's side kept, as VTK's
 * mappers). Where a ray enters the kept region inside the mesh (the camera
 * inside the mesh, a clipping plane through it) it starts with a synthetic
 * entry fragment (Face == StartFace) whose scalar is interpolated in the
 * tetrahedron that holds the start point (vtkStaticCellLocator, barycentric
 * weights); where it leaves the kept region inside the mesh it ends with a
 * synthetic exit fragment (Face == EndFace), its scalar interpolated between
 * the fragments around it. Faces wholly on the discarded side of a plane are
 * not traversed.
 *
 * The per-pixel fragments (distance, scalar, face, exit flag) are kept for the
 * k-requirement analysis and the software k-buffer.
 */
#ifndef vtkHAVSReferenceRenderer_h
#define vtkHAVSReferenceRenderer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSValidationModule.h" // For export macro
#include "vtkNew.h"                  // For vtkNew
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <cmath>   // For std::isnan
#include <cstdint> // For uint32_t
#include <limits>  // For std::numeric_limits
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkCamera;
class vtkDataSet;
class vtkFloatArray;
class vtkLightCollection;
class vtkHAVSFaceSet;
class vtkHAVSIsoSurfaces;
class vtkMatrix4x4;
class vtkPlaneCollection;
class vtkPolyData;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

class VTKHAVSVALIDATION_EXPORT vtkHAVSReferenceRenderer : public vtkObject
{
public:
  static vtkHAVSReferenceRenderer* New();
  vtkTypeMacro(vtkHAVSReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene: grid, property, camera, the volume's matrix (identity when
   * none), image size. The grid: any vtkDataSet, split into tetrahedra as the
   * mappers split it (vtkHAVSTetrahedralizer); its active point scalars, or
   * its active cell scalars when it has no point scalars or
   * SetUseCellScalars(true) (each segment in one cell, integrated constant).
   */
  void SetInputData(vtkDataSet* grid);
  void SetProperty(vtkVolumeProperty* property);
  void SetCamera(vtkCamera* camera);
  void SetVolumeMatrix(vtkMatrix4x4* matrix);
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * Clipping planes (world coordinates; each keeps the side its normal points
   * to), as vtkAbstractMapper::SetClippingPlanes. At most 6 are used.
   */
  void SetClippingPlanes(vtkPlaneCollection* planes);
  vtkPlaneCollection* GetClippingPlanes();
  ///@}

  ///@{
  /// Render the active cell scalars even where point scalars exist (off by default).
  vtkSetMacro(UseCellScalars, bool);
  vtkGetMacro(UseCellScalars, bool);
  /**
   * The subdivision of quadratic and higher-order cells, as the mappers'
   * SetHigherOrderSubdivision (0, the default: their nodes only), so that the
   * reference sees the tessellation the mapper draws.
   */
  void SetHigherOrderSubdivision(int level);
  vtkGetMacro(HigherOrderSubdivision, int);
  /// Whether the last ComputeFragments() used cell scalars.
  vtkGetMacro(CellScalarsUsed, bool);
  ///@}

  ///@{
  /**
   * Whether rays start at the camera's near plane (as every rasterizing
   * mapper's do). On by default.
   */
  vtkSetMacro(NearPlaneClipping, bool);
  vtkGetMacro(NearPlaneClipping, bool);
  vtkBooleanMacro(NearPlaneClipping, bool);
  ///@}

  ///@{
  /**
   * Opaque geometry in the scene: a depth image of Size (window depth values
   * in [0, 1], bottom row first, as vtkRenderWindow::GetZbufferData gives);
   * each ray ends at its depth (1: nothing there). nullptr: none.
   */
  void SetOpaqueDepth(vtkFloatArray* depth);
  ///@}

  ///@{
  /**
   * Translucent surfaces in the scene, as layers of fragments (a depth image
   * of Size as SetOpaqueDepth's, 1 where the layer has no fragment, and a
   * colour image: RGB not premultiplied and opacity, as
   * vtkHAVSTranslucentLayers peels them from VTK's own render). Under the
   * composite and isosurface blends (and the mixed mode) each fragment is an
   * event along its pixel's ray: the
   * segment it falls in is split at its distance (the scalar linear along
   * the segment) and the fragment is composited between the two pieces;
   * fragments outside the mesh are composited in their order too.
   */
  void AddTranslucentLayer(vtkFloatArray* depth, vtkFloatArray* rgba);
  /**
   * A translucent surface given as polygons (world coordinates) of one
   * colour and opacity (`rgba`, not premultiplied: an unlit surface, or one
   * lit by ambient light alone): every polygon is rasterized exactly at the
   * pixel centres (vtkHAVSFaceRasterizer, watertight) and each hit is an event
   * as a layer's fragment is (in front of the near plane and behind the
   * opaque depth: none).
   */
  void AddTranslucentSurface(vtkPolyData* surface, const double rgba[4]);
  /// Removes the layers and the surfaces.
  void RemoveAllTranslucentLayers();
  int GetNumberOfTranslucentLayers() const
  {
    return static_cast<int>(this->TranslucentLayers.size());
  }
  /// A surface fragment along a ray: its distance (as Fragment::Distance) and premultiplied colour.
  struct SurfaceEvent
  {
    double Distance;
    double RGBA[4];
  };
  ///@}

  ///@{
  /**
   * The blend mode, numbered as vtkVolumeMapper's: COMPOSITE_BLEND (0, the
   * default: the optical model above), MAXIMUM_INTENSITY_BLEND (1) and
   * MINIMUM_INTENSITY_BLEND (2: the extremal scalar over the ray's segments in
   * the mesh, premultiplied colour * opacity and opacity of it, from the
   * property's functions; nothing where the ray misses), ADDITIVE_BLEND (4:
   * the integral of tau(s) s_n along the ray, s_n the scalar normalized to
   * GetScalarRange(), integrated adaptively per segment, clamped to 1, grey
   * with opacity 1 where the ray crosses the mesh), ISOSURFACE_BLEND (5: the
   * property's isovalues crossed along the ray, each the transfer functions'
   * premultiplied colour and opacity at its value, composited front to back,
   * nothing between them: vtkHAVSIsoSurfaces). Others: composite.
   * IsoSurfacesInComposite: the composite blend with the same surfaces
   * inside the volume (each segment split at its crossings, the pieces
   * integrated exactly), the mappers' mixed mode.
   */
  vtkSetMacro(BlendMode, int);
  vtkGetMacro(BlendMode, int);
  vtkSetMacro(IsoSurfacesInComposite, bool);
  vtkGetMacro(IsoSurfacesInComposite, bool);
  ///@}

  /**
   * The lights that shade the isosurfaces where the property's Shade is on
   * (vtkHAVSIsoSurfaces::MakeShading and Shade, the mappers' model): a
   * renderer's GetLights() after it rendered (its lights then follow its
   * camera). The normal at a crossing is the interpolated point gradients'
   * (vtkHAVSPointGradients over this renderer's tetrahedra, world
   * coordinates): each fragment takes its face's interpolation, a crossing
   * the mix of its segment's two ends. nullptr (the default): ambient only.
   */
  void SetLights(vtkLightCollection* lights);

  /// Face ids of the synthetic fragments where a ray enters or leaves the
  /// region kept by the near and clipping planes inside the mesh.
  static constexpr uint32_t StartFace = 0xFFFFFFFEu;
  static constexpr uint32_t EndFace = 0xFFFFFFFFu;

  /// Pixels whose ray started inside the mesh at a plane, in the last frame.
  vtkGetMacro(NumberOfStartedInside, vtkIdType);

  /**
   * MISSION.md's folded pixels: those whose ray crosses a folded cell (one of
   * the two tetrahedra of an internal face with both on one side: an inverted
   * cell and the cell it overlaps, vtkHAVSVisibilityOrder), where no image is
   * exact. `mask` (Size pixels, bottom row first) gets 1 there; returns how
   * many (0 for a mesh without folds). Uses the fragments of the last
   * ComputeFragments() or Render() (computes them when there are none).
   */
  vtkIdType ComputeFoldedPixels(std::vector<uint8_t>& mask);

  /// One hit of a pixel's ray with a face.
  struct Fragment
  {
    double Distance; ///< along the ray from the eye (parallel: along the view direction)
    double Scalar;   ///< the scalar on the near side (a segment ending here ends at it)
    uint32_t Face;   ///< index in GetFaceSet()
    bool Boundary;
    bool Exit; ///< a boundary face seen from inside
    /// Cell scalars: the value of the cell behind the fragment (a segment
    /// starting here has it); NaN for point scalars (then Scalar on both sides).
    double Behind = std::numeric_limits<double>::quiet_NaN();
    /// The scalar a segment starting at this fragment starts with.
    double ScalarBehind() const { return std::isnan(this->Behind) ? this->Scalar : this->Behind; }
    /// The interpolated point gradients here (world; only where isosurfaces are shaded).
    float Gradient[3] = { 0.0f, 0.0f, 0.0f };
  };

  /**
   * Finds every pixel's fragments, sorted by distance. Returns false with an
   * error for a missing or unusable input.
   */
  bool ComputeFragments();

  /**
   * ComputeFragments() if needed, then the exact image (premultiplied RGBA,
   * bottom row first) in GetImage().
   */
  bool Render();

  vtkFloatArray* GetImage() { return this->Image; }

  /// The faces the fragments refer to, of the tetrahedralized input: built again
  /// only when that changes (orders built on it, vtkHAVSVisibilityOrder, stay
  /// valid across renders).
  vtkHAVSFaceSet* GetFaceSet() { return this->Faces; }

  ///@{
  /// The fragments of pixel p (= y * width + x), sorted by distance.
  const Fragment* GetPixelFragmentsBegin(vtkIdType p) const
  {
    return this->Fragments.data() + this->PixelStart[p];
  }
  const Fragment* GetPixelFragmentsEnd(vtkIdType p) const
  {
    return this->Fragments.data() + this->PixelStart[p + 1];
  }
  vtkIdType GetNumberOfFragments() const { return static_cast<vtkIdType>(this->Fragments.size()); }
  ///@}

  /// The normalized scalar mapping (the mapper's): (s - range[0]) / span.
  const double* GetScalarRange() const { return this->ScalarRange; }

  /**
   * The premultiplied colour of a ray integrated over its sorted fragments
   * (the exact answer for one pixel).
   */
  static void IntegrateRay(
    vtkVolumeProperty* property, const Fragment* begin, const Fragment* end, double rgba[4]);

  /**
   * One pixel under `blendMode` (see SetBlendMode); `scalarRange` normalizes
   * the scalars for the additive blend.
   */
  static void IntegrateRayBlend(vtkVolumeProperty* property, const Fragment* begin,
    const Fragment* end, int blendMode, const double scalarRange[2], double rgba[4]);

  /**
   * One pixel with isosurfaces `iso` (vtkHAVSIsoSurfaces::Make: the
   * isosurface blend, or the composite blend's mixed mode): the surfaces'
   * colours from `property` at their values, the volume's pieces between
   * them exactly (IntegrateSegmentExact) in the mixed mode.
   */
  static void IntegrateRayIso(vtkVolumeProperty* property, const Fragment* begin,
    const Fragment* end, const vtkHAVSIsoSurfaces& iso, double rgba[4],
    const double* toEye = nullptr);
  /**
   * One pixel with surface fragments (`events` sorted by distance) composited
   * between the volume's pieces: the composite blend, or with `iso` its
   * surfaces (IntegrateRayIso: the isosurface blend, or the mixed mode).
   */
  static void IntegrateRayWithSurfaces(vtkVolumeProperty* property, const Fragment* begin,
    const Fragment* end, const SurfaceEvent* eventsBegin, const SurfaceEvent* eventsEnd,
    double rgba[4], const vtkHAVSIsoSurfaces* iso = nullptr, const double* toEye = nullptr);

  /**
   * The additive blend's segment: the integral of tau(s(t)) (s(t) - lo) /
   * span over the segment (sf -> sb linear, `length`), split at the opacity
   * nodes, each piece adaptively (Simpson) to 1e-9 per unit length.
   */
  static double IntegrateAdditiveSegment(
    vtkVolumeProperty* property, double sf, double sb, double length, const double scalarRange[2]);

  /**
   * The segment (sf -> sb, length) split at the property's transfer-function
   * nodes and integrated piece by piece to 1e-6.
   */
  static void IntegrateSegmentExact(
    vtkVolumeProperty* property, double sf, double sb, double length, double rgba[4]);

protected:
  vtkHAVSReferenceRenderer();
  ~vtkHAVSReferenceRenderer() override;

private:
  vtkHAVSReferenceRenderer(const vtkHAVSReferenceRenderer&) = delete;
  void operator=(const vtkHAVSReferenceRenderer&) = delete;

  /// Invokes vtkCommand::ProgressEvent with the progress (0 … 1) as call data.
  void ReportProgress(double progress);
  double ProgressRange[2] = { 0.0, 1.0 }; // what ReportProgress's 0 … 1 maps to

  vtkSmartPointer<vtkDataSet> Source;         // what SetInputData was given
  vtkSmartPointer<vtkUnstructuredGrid> Input; // it as tetrahedra
  bool UseCellScalars = false;
  int HigherOrderSubdivision = 0;
  bool CellScalarsUsed = false;
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkCamera> Camera;
  vtkNew<vtkMatrix4x4> VolumeMatrix;
  int Size[2] = { 64, 64 };
  vtkNew<vtkHAVSFaceSet> Faces;
  vtkUnstructuredGrid* FacesInput = nullptr; // the input Faces was built on (compared only)
  bool FacesValid = false;
  vtkNew<vtkFloatArray> Image;
  vtkSmartPointer<vtkPlaneCollection> ClippingPlanes;
  bool NearPlaneClipping = true;
  int BlendMode = 0;
  bool IsoSurfacesInComposite = false;
  vtkSmartPointer<vtkFloatArray> OpaqueDepth;
  struct TranslucentLayer
  {
    vtkSmartPointer<vtkFloatArray> Depth;
    vtkSmartPointer<vtkFloatArray> RGBA;
  };
  std::vector<TranslucentLayer> TranslucentLayers;
  struct TranslucentSurface
  {
    vtkSmartPointer<vtkPolyData> Surface;
    double RGBA[4];
  };
  std::vector<TranslucentSurface> TranslucentSurfaces;
  std::vector<SurfaceEvent> SurfaceEvents;  ///< per pixel, sorted (ComputeFragments)
  std::vector<vtkIdType> SurfaceEventStart; ///< pixel p's events: [start[p], start[p + 1])
  vtkIdType NumberOfStartedInside = 0;
  std::vector<Fragment> Fragments;
  std::vector<vtkIdType> PixelStart;
  vtkSmartPointer<vtkLightCollection> Lights;
  bool ShadeIsoSurfaces = false;       ///< this frame's fragments carry gradients
  std::vector<double> PixelDirections; ///< (shaded isosurfaces) each pixel's ray direction
  double ScalarRange[2] = { 0.0, 1.0 };
};

VTK_ABI_NAMESPACE_END
#endif
