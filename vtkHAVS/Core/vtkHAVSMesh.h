/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMesh.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSMesh
 * @brief   The mesh as vtkHAVSVolumeMapper renders it: faces, float points, scalars.
 *
 * Plain C++, no OpenGL. Built from the mapper's input and scalar selection
 * only when they change (not for a new camera, k, table or clipping plane):
 * - the input as tetrahedra (vtkHAVSTetrahedralizer: any vtkDataSet; cells
 *   that are not tetrahedra split consistently across shared faces);
 * - the unique triangular faces of the tetrahedra (vtkHAVSFaceSet: boundary
 *   faces wound outward, degenerate cells dropped);
 * - the points minus the bounds' centre (the shift), as floats, so that far
 *   from the origin the GPU keeps float precision;
 * - the scalars (point or cell data; one component, or the magnitude, as
 *   the vector mode says) mapped to [0, 1] over their finite range, NaN and
 *   infinite values replaced by the lowest finite one.
 * Point scalars are drawn at the shared points, interpolated across faces.
 * Cell scalars are constant in each cell: a segment lies in one cell, so a
 * fragment carries the cell behind it. Each face is then drawn with vertices
 * of its own carrying two cell codes (the cell on its normal's side, the cell
 * on the other; a code indexes the cell's value among the distinct ones,
 * vtkHAVSCellOptics), and the fragment picks one by its facing
 * (GetVertexScalarComponents() is 2).
 * Build() says why when nothing can be rendered (GetError()) and what it
 * changed or left out (GetWarnings()); the mapper reports both.
 */
#ifndef vtkHAVSMesh_h
#define vtkHAVSMesh_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h"      // For export macro
#include "vtkHAVSMemory.h"          // For vtkHAVSMemory::Bytes
#include "vtkHAVSTetrahedralizer.h" // For vtkHAVSTetrahedralizer::Report
#include "vtkNew.h"                 // For vtkNew
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkDataArray;
class vtkDataObject;
class vtkDataSet;
class vtkHAVSFaceSet;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSMesh : public vtkObject
{
public:
  static vtkHAVSMesh* New();
  vtkTypeMacro(vtkHAVSMesh, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How a multi-component array becomes one scalar (as vtkSmartVolumeMapper's VectorModeType).
  enum VectorModes
  {
    VectorModeDisabled = -1, ///< the first component
    VectorModeMagnitude = 0, ///< the Euclidean norm of the components
    VectorModeComponent = 1  ///< the component VectorComponent
  };

  /// Which scalars: vtkAbstractMapper's scalar mode, array access, id, name; the vector mode.
  struct ScalarSelection
  {
    int Mode = 0;
    int AccessMode = 0;
    int Id = -1;
    std::string Name;
    int VectorMode = VectorModeDisabled;
    int VectorComponent = 0;
    /// vtkHAVSTetrahedralizer's subdivision level of non-linear cells (0: their nodes only).
    int HigherOrderSubdivision = 0;
    bool operator==(const ScalarSelection& o) const
    {
      return this->Mode == o.Mode && this->AccessMode == o.AccessMode && this->Id == o.Id &&
        this->Name == o.Name && this->VectorMode == o.VectorMode &&
        this->VectorComponent == o.VectorComponent &&
        this->HigherOrderSubdivision == o.HigherOrderSubdivision;
    }
  };

  /// Whether Build() would do anything for this input and selection.
  bool NeedsBuild(vtkDataObject* input, const ScalarSelection& selection) const;

  /**
   * Builds the mesh. Returns false, with GetError() set, when nothing can be
   * rendered. `progress` (optional) is called with 0 … 1.
   */
  bool Build(vtkDataObject* input, const ScalarSelection& selection,
    const std::function<void(double)>& progress = nullptr);

  /// Whether the last Build() succeeded.
  bool IsValid() const { return this->Valid; }
  /**
   * Modified at every Build() that made the mesh again (successful or not):
   * not for a new time step on the same mesh, whose Build() only maps the
   * new scalars (GetScalarTime()).
   */
  vtkMTimeType GetBuildTime() const { return this->BuildTime.GetMTime(); }
  /// Modified whenever the scalars were mapped (every successful Build()).
  vtkMTimeType GetScalarTime() const { return this->ScalarTime.GetMTime(); }

  /// What the last Build() did: the whole mesh, the scalars only, or nothing
  /// (it failed, or the input was another data object around the same points,
  /// cells and scalar array).
  enum Updates
  {
    UpdateNone,
    UpdateFull,
    UpdateScalars
  };
  int GetLastUpdate() const { return this->LastUpdate; }
  /// Seconds the last Build() took.
  double GetLastUpdateSeconds() const { return this->LastUpdateSeconds; }

  /**
   * A hash of a data set's geometry: its type, counts, point coordinates,
   * cells and ghost flags (what the faces depend on), not its arrays.
   */
  static uint64_t GeometryHashOf(vtkDataSet* data);

  /// Why the last Build() failed (empty when it did not).
  const std::string& GetError() const { return this->Error; }
  /// What the last Build() changed or left out (skipped cells, NaN scalars …).
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }

  /**
   * Zero-volume tetrahedra contribute nothing to any ray, and those thinner
   * than vtkHAVSFaceSet::MinimumRelativeThickness of the mesh's extent across
   * them nothing a float pipeline can resolve: they are dropped
   * and counted (GetFaceSet()->GetNumberOfDegenerateTetrahedra(), the mappers'
   * GetNumberOfDegenerateTetrahedra()). Only when they are more than this
   * share of the tetrahedra (a broken mesh rather than a mesher's slivers:
   * the blunt fin has 77 of 187,395) does Build() warn.
   */
  static constexpr double DegenerateWarningShare = 0.01;

  vtkHAVSFaceSet* GetFaceSet() { return this->Faces; }
  /// The tetrahedral grid the faces were built from (the input when it was one).
  vtkUnstructuredGrid* GetGrid();
  /// What the tetrahedralization did (Tessellated false: the input was used).
  const vtkHAVSTetrahedralizer::Report& GetTessellation() const { return this->Tessellation; }
  /// Three floats per point: grid coordinates minus GetShift().
  const std::vector<float>& GetPoints() const { return this->Points; }
  /**
   * One per point, in [0, 1] over GetScalarRange(). With cell scalars, each
   * point's value is that of one cell using it: only for what needs a value
   * per point and cannot see the cell (nothing that draws does).
   */
  const std::vector<float>& GetScalars() const { return this->Scalars; }

  ///@{
  /**
   * Cell scalars: whether the scalars are the cells'; then one value per used
   * tetrahedron (the faces' GetTetrahedra() order), in [0, 1].
   */
  bool HasCellScalars() const { return this->CellScalars; }
  const std::vector<float>& GetTetrahedronScalars() const { return this->TetrahedronScalars; }
  ///@}

  ///@{
  /**
   * Cell scalars as the passes draw them (vtkHAVSCellOptics): the distinct
   * values of the used cells, sorted (NaN/Inf replaced as in the scalars;
   * rounded to a grid when there are more than vtkHAVSCellOptics::MaximumValues,
   * with a warning), and each used tetrahedron's code: the index of its value
   * among them, as vtkHAVSCellOptics::CodeOf. GetVertexScalars() and the
   * sections carry these codes.
   */
  const std::vector<double>& GetCellValues() const { return this->CellValues; }
  const std::vector<float>& GetTetrahedronCodes() const { return this->TetrahedronCodes; }
  ///@}

  ///@{
  /**
   * What the face passes draw: vertices (3 floats each, as GetPoints()), their
   * scalars (GetVertexScalarComponents() floats each) and the faces as 3
   * vertex ids each, in face order. Point scalars: the points, their scalars,
   * the faces' point ids (1 component). Cell scalars: 3 vertices of its own
   * per face, each with (the code of the cell on the face's normal side, that
   * of the cell on the other side; GetTetrahedronCodes()); a boundary face
   * has its one cell's code on both (2 components).
   */
  const std::vector<float>& GetVertexPoints() const;
  const std::vector<float>& GetVertexScalars() const;
  const std::vector<uint32_t>& GetFaceVertexIds() const;
  int GetVertexScalarComponents() const { return this->CellScalars ? 2 : 1; }
  ///@}

  /**
   * Boundary tagging's vertices: every face of `triangles` (3 vertex ids
   * each, in draw order) flagged in `boundary` gets three vertices of its
   * own, appended in draw order after the `points`' (GetVertexPoints()):
   * their points in `taggedPoints`, their scalars plus 2 (the tag the draw
   * shader reads; flag 2 with two components swaps the pair) in
   * `taggedScalars`; `indices` is `triangles` with those faces' ids
   * rewritten (empty without boundary faces: `triangles` are drawn as they
   * are). What the GPU draws with tagging on (vtkHAVSGLMesh) and what
   * the stand-alone GPU program's cases hold (Apps/GPUBench). With
   * `vectors` (3 floats a point, as `points`: the shaded isosurfaces' point
   * gradients), their copies too in `taggedVectors`. Returns the number of
   * boundary faces.
   */
  static size_t MakeTaggedVertices(const std::vector<float>& points,
    const std::vector<float>& scalars, int components, const std::vector<uint32_t>& triangles,
    const std::vector<uint8_t>& boundary, std::vector<float>& taggedPoints,
    std::vector<float>& taggedScalars, std::vector<uint32_t>& indices,
    const std::vector<float>* vectors = nullptr, std::vector<float>* taggedVectors = nullptr);
  const double* GetShift() const { return this->Shift; }
  /// The points' bounds in model coordinates (shifted).
  const double* GetBounds() const { return this->Bounds; }
  /// The length of the bounds' diagonal.
  double GetDiagonal() const;
  /// The finite range of the scalars rendered.
  const double* GetScalarRange() const { return this->ScalarRange; }
  /// The property component whose functions colour the scalars (always 0), and how many
  /// components the array has.
  int GetComponent() const { return this->Component; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }
  /// How the array's components became the scalar rendered: a text for messages.
  const std::string& GetScalarDescription() const { return this->ScalarDescription; }

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSMesh();
  ~vtkHAVSMesh() override;

private:
  vtkHAVSMesh(const vtkHAVSMesh&) = delete;
  void operator=(const vtkHAVSMesh&) = delete;

  bool Fail(const std::string& why);
  /// The selected scalar of tuple i (component or magnitude).
  double ScalarOf(vtkDataArray* array, vtkIdType i) const;
  /// The per-face vertices of cell scalars (GetVertexPoints() and the rest),
  /// from each cell's code.
  void BuildCellScalarVertices(const std::vector<float>& cellCodes);
  /// CellValues from the used cells' (finite) values, and each used cell's code.
  void BuildCellValueCodes(
    const std::vector<double>& values, const std::vector<uint8_t>& used, std::vector<float>& codes);
  /// Maps `scalars` (of the grid's points or cells) to [0, 1] (the last part of Build()).
  bool MapScalars(vtkDataArray* scalars, bool cellData, const std::string& arrayName);

  vtkNew<vtkHAVSFaceSet> Faces;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  vtkHAVSTetrahedralizer::Report Tessellation;
  vtkHAVSTetrahedralizer::SourceMap Sources; // a tessellated mesh's, for new time steps
  std::vector<float> Points;
  std::vector<float> Scalars;
  bool CellScalars = false;
  std::vector<float> TetrahedronScalars;
  std::vector<float> TetrahedronCodes;
  std::vector<double> CellValues;
  std::vector<float> FaceVertexPoints;  // cell scalars: 9 floats per face
  std::vector<float> FaceVertexScalars; // cell scalars: 6 floats per face
  std::vector<uint32_t> FaceVertexIds;  // cell scalars: 3f, 3f + 1, 3f + 2
  std::string ScalarDescription;
  int VectorMode = VectorModeDisabled;
  int VectorComponent = 0;
  double Shift[3] = { 0, 0, 0 };
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  double ScalarRange[2] = { 0, 1 };
  int Component = 0;
  int NumberOfComponents = 1;
  bool Valid = false;
  std::string Error;
  std::vector<std::string> Warnings;

  // What the mesh was built from.
  vtkDataObject* BuiltInput = nullptr; // identity only, never dereferenced
  vtkMTimeType BuiltInputTime = 0;
  ScalarSelection BuiltSelection;
  vtkTimeStamp BuildTime;
  vtkTimeStamp ScalarTime;
  uint64_t GeometryHash = 0;
  vtkDataSet* HashedSource = nullptr;       // identity only: whether GeometryHash is set
  vtkWeakPointer<vtkDataArray> MappedArray; // the scalar array last mapped, and its time
  vtkMTimeType MappedArrayTime = 0;
  int LastUpdate = UpdateNone;
  double LastUpdateSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif
