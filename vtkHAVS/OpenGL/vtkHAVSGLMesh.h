/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMesh.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLMesh
 * @brief   The mesh on the GPU: points, scalars, faces in draw order, sections.
 *
 * Points (3 floats, model coordinates) and normalized scalars are uploaded
 * once per mesh; the triangles in draw order once per new face order (with
 * tagging, each boundary face on vertices of its own whose scalar tells the
 * shader its role); the sections of the near and clipping planes when they
 * change. Each Update* method uploads only when its version changed. DrawFaces()
 * draws, in this order along every ray, the sections that enter the clipped
 * volume, the faces, the sections that leave it.
 */
#ifndef vtkHAVSGLMesh_h
#define vtkHAVSGLMesh_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSFramePlanes.h" // For vtkHAVSFramePlanes::Section
#include "vtkHAVSGLObjects.h"   // For vtkHAVSGLBuffer, vtkHAVSGLVertexArray
#include "vtkHAVSOpenGL.h"      // For GLuint
#include "vtkObject.h"
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>

#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSMesh;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

class vtkHAVSGLMesh : public vtkObject
{
public:
  static vtkHAVSGLMesh* New();
  vtkTypeMacro(vtkHAVSGLMesh, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The context every buffer lives in (set before any upload).
  void SetContext(vtkOpenGLRenderWindow* window) { this->Window = window; }

  /// Points (3 floats each, model coordinates) and normalized scalars (in
  /// [0, 1], `components` per vertex: 1 for point scalars, 2 for the two cells
  /// of a face's own vertices, vtkHAVSMesh::GetVertexScalars); kept on the
  /// host too, for the boundary vertices. Sections get as many per vertex.
  void UploadGeometry(
    const std::vector<float>& points, const std::vector<float>& scalars, int components = 1);
  /**
   * The faces in draw order (3 point ids each) and their boundary flags. With
   * `tagged`, each boundary face is drawn with vertices of its own, appended
   * after the points, whose scalar is the point's + 2: the fragment shader
   * tells a boundary fragment by its scalar (above 1.5), with no per-fragment
   * look-up, and only boundary fragments do the tagging work. Flag 2 (a face
   * wound against its cell-scalar pairs, vtkHAVSFaceOrderPolicy) swaps the
   * pair on those vertices.
   */
  bool UploadFaceOrder(
    const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& boundary, bool tagged);
  /// New scalars for the uploaded points (a new time step on the same mesh),
  /// as many as UploadGeometry had; the boundary vertices take them at the next
  /// UploadFaceOrder.
  void UploadScalars(const std::vector<float>& scalars);
  /// The sections of the next frames (empty: none).
  void UploadSections(
    const std::vector<vtkHAVSFramePlanes::Section>& sections, const std::vector<uint32_t>& tets);

  ///@{
  /**
   * The same, each only when its version (a modification time) is not the
   * one uploaded last: the mesh's points and scalars (vtkHAVSMesh's build
   * and scalar times; new scalars only for a new time step), the face order
   * (and whether it went up tagged), the sections. Each says what it
   * uploaded; a new geometry or scalars make the next face order upload
   * (the boundary vertices copy them).
   */
  enum GeometryUploads
  {
    UploadedNothing = 0,
    UploadedGeometry = 1,
    UploadedScalars = 2
  };
  int UpdateGeometry(vtkHAVSMesh* mesh);
  /// False when nothing was uploaded; `failed` when the upload failed.
  bool UpdateFaceOrder(const std::vector<uint32_t>& triangles, const std::vector<uint8_t>& boundary,
    bool tagged, vtkMTimeType version, bool* failed);
  /// The sections (again when `version` or the gradients changed); `tets`:
  /// the mesh's tetrahedra, which the sections' Cells index (shaded
  /// isosurfaces: the gradients interpolated at the sections' vertices).
  bool UpdateSections(const std::vector<vtkHAVSFramePlanes::Section>& sections,
    vtkMTimeType version, const std::vector<uint32_t>& tets);
  /**
   * Shaded isosurfaces (HAVS's fragment lists): each point's gradient (3
   * floats, model coordinates, as GetPoints()) at attribute 2, the boundary
   * vertices' copies with the next face order; uploaded when `version`
   * changed. nullptr: none (the face orders copy no gradients).
   */
  bool UpdateGradients(const std::vector<float>* gradients, vtkMTimeType version);
  ///@}

  vtkIdType GetNumberOfFaces() const { return this->IndexCount / 3; }
  /// Scalars per vertex (1 point scalars, 2 cell scalars).
  int GetComponents() const { return this->Components; }
  /// Whether the next frames draw plane sections.
  bool HasSections() const { return !this->SectionDraws.empty(); }

  /**
   * Reads back what DrawFaces draws (for vtkHAVSGLFrameCapture): the vertex
   * buffers (3 floats and 1 scalar per vertex, boundary vertices included)
   * and the indices in draw order.
   */
  void ReadBack(
    std::vector<float>& points, std::vector<float>& scalars, std::vector<uint32_t>& indices) const;

  /**
   * Draws, with `program` bound: the entering sections, the faces (front
   * faces counter-clockwise, or clockwise for a mirroring volume matrix), the
   * leaving sections. Sets havsRole and havsOwnPlane for the sections where
   * the program uses them. The faces go in `batches` draw calls of about
   * equal size; `betweenBatches(b)` runs after batch b (all but the last),
   * and must leave `program` bound again.
   */
  void DrawFaces(vtkShaderProgram* program, bool flipFacing, int batches = 1,
    const std::function<void(int)>& betweenBatches = nullptr);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkHAVSGLMesh();
  ~vtkHAVSGLMesh() override;

private:
  vtkHAVSGLMesh(const vtkHAVSGLMesh&) = delete;
  void operator=(const vtkHAVSGLMesh&) = delete;

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkHAVSGLVertexArray VertexArray;
  vtkHAVSGLBuffer PointBuffer;
  vtkHAVSGLBuffer ScalarBuffer;
  vtkHAVSGLBuffer IndexBuffer;
  GLsizei IndexCount = 0;
  std::vector<float> Points; // as uploaded, for the boundary vertices
  std::vector<float> Scalars;
  size_t VertexCapacity = 0;      // vertices the point and scalar buffers hold
  int Components = 1;             // scalars per vertex
  vtkHAVSGLBuffer GradientBuffer; // (shaded isosurfaces) attribute 2
  std::vector<float> Gradients;   // as uploaded (empty: none this frame)
  /// Whether this frame's vertices carry gradients (one per point).
  bool HasGradients() const
  {
    return !this->Gradients.empty() && this->Gradients.size() == this->Points.size();
  }
  vtkMTimeType GradientsVersion = 0;

  vtkHAVSGLVertexArray SectionArray;
  vtkHAVSGLBuffer SectionPoints;
  vtkHAVSGLBuffer SectionScalars;
  vtkHAVSGLBuffer SectionGradients; // (shaded isosurfaces) attribute 2
  vtkMTimeType SectionsGradientsVersion = 0;
  struct SectionDraw
  {
    int PlaneIndex;
    bool Entering;
    GLint First;
    GLsizei Count;
  };
  std::vector<SectionDraw> SectionDraws;

  // The versions on the GPU (0: none).
  vtkMTimeType GeometryVersion = 0;
  vtkMTimeType ScalarVersion = 0;
  vtkMTimeType OrderVersion = 0;
  bool OrderTagged = false;
  vtkMTimeType SectionsVersion = 0;
};

VTK_ABI_NAMESPACE_END
#endif
