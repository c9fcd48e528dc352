/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFramePlanes.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFramePlanes
 * @brief   The near and clipping planes of a frame, and the mesh's sections with them.
 *
 * Plain C++, no OpenGL. Every fragment outside a plane is discarded on the
 * GPU; where a plane cuts the mesh, the rays enter (or leave) the clipped
 * volume where no face lies, so the mesh's section with the plane
 * (vtkHAVSPlaneSection) is drawn there as entry (exit) fragments carrying the
 * interpolated scalar. The near plane counts only where it cuts the mesh's
 * bounds (a camera inside the mesh); up to 6 clipping planes (world
 * coordinates, the normal's side kept, as VTK's other mappers). Sections are
 * made again only when a cut plane or the mesh changed
 * (GetSectionsVersion()).
 */
#ifndef vtkHAVSFramePlanes_h
#define vtkHAVSFramePlanes_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkNew.h"            // For vtkNew
#include "vtkObject.h"

#include <array>  // For std::array
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSMesh;
class vtkHAVSPlaneSection;
class vtkHAVSViewFrame;
class vtkPlaneCollection;

class VTKHAVSCORE_EXPORT vtkHAVSFramePlanes : public vtkObject
{
public:
  static vtkHAVSFramePlanes* New();
  vtkTypeMacro(vtkHAVSFramePlanes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr int MaximumClippingPlanes = 6;

  /**
   * A section with plane PlaneIndex: triangles (3 points of 3 floats, model
   * coordinates, and 3 normalized scalars each), drawn as entries into the
   * clipped volume before the faces (Entering) or as exits after them.
   */
  struct Section
  {
    int PlaneIndex = 0;
    bool Entering = true;
    std::vector<float> Points;
    std::vector<float> Scalars;
    std::vector<uint32_t> Cells; ///< the tetrahedron of each triangle
  };

  /**
   * The planes of a frame. `sections`: make the sections (off only for a
   * comparison). Returns false when more clipping planes were given than are
   * used (the first MaximumClippingPlanes are).
   */
  bool Update(
    const vtkHAVSViewFrame& view, vtkPlaneCollection* clipping, vtkHAVSMesh* mesh, bool sections);

  ///@{
  /**
   * Sections of the near plane only (for vtkHAVSCellProjectionMapper: a
   * clipping plane needs none there, the ray starts on it inside the cell
   * whose front face the rasterizer still draws). Off by default.
   */
  vtkSetMacro(NearPlaneSectionsOnly, bool);
  vtkGetMacro(NearPlaneSectionsOnly, bool);
  ///@}

  /// Planes that cut or discard the mesh (the near plane first when it does).
  int GetNumberOfPlanes() const { return static_cast<int>(this->Planes.size()); }
  /// Whether the near plane cuts or discards the mesh's bounds this frame
  /// (then it is plane 0; rays may start inside the mesh).
  bool GetNearPlaneCutsMesh() const { return this->NearPlaneCutsMesh; }
  /// Plane i in eye-relative world coordinates: kept where dot(xyz, x) + w >= 0.
  const std::array<float, 4>& GetPlane(int i) const { return this->Planes[i]; }
  /// Plane i in the mesh's model coordinates (double), kept where >= 0.
  const std::array<double, 4>& GetModelPlane(int i) const { return this->ModelPlanes[i]; }
  const std::vector<Section>& GetSections() const { return this->Sections; }
  /// Changes whenever the sections do.
  vtkMTimeType GetSectionsVersion() const { return this->SectionsTime.GetMTime(); }
  /// Triangles of the sections, and the seconds their last computation took.
  vtkIdType GetNumberOfSectionTriangles() const { return this->SectionTriangles; }
  double GetSectionSeconds() const { return this->SectionSeconds; }

protected:
  vtkHAVSFramePlanes();
  ~vtkHAVSFramePlanes() override;

private:
  vtkHAVSFramePlanes(const vtkHAVSFramePlanes&) = delete;
  void operator=(const vtkHAVSFramePlanes&) = delete;

  /// A plane that cuts the mesh: its index among the planes, whether the rays
  /// enter the kept side there, its equation in model coordinates.
  struct Cut
  {
    int Index;
    bool Entering;
    std::array<double, 4> PlaneModel;
    bool operator==(const Cut& o) const
    {
      return this->Index == o.Index && this->Entering == o.Entering &&
        this->PlaneModel == o.PlaneModel;
    }
  };

  bool NearPlaneSectionsOnly = false;
  bool NearPlaneCutsMesh = false;
  std::vector<std::array<float, 4>> Planes;
  std::vector<std::array<double, 4>> ModelPlanes;
  std::vector<Section> Sections;
  std::vector<Cut> Cuts; // what the sections were made for
  vtkMTimeType CutsMeshTime = 0;
  vtkTimeStamp SectionsTime;
  vtkIdType SectionTriangles = 0;
  double SectionSeconds = 0.0;
  vtkNew<vtkHAVSPlaneSection> Sectioner;
};

VTK_ABI_NAMESPACE_END
#endif
