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
 * - the unique triangular faces of the tetrahedra (vtkHAVSFaceSet: boundary
 *   faces wound outward, degenerate cells dropped, other cells skipped);
 * - the points minus the bounds' centre (the shift), as floats, so that far
 *   from the origin the GPU keeps float precision;
 * - the scalars of the selected component mapped to [0, 1] over their finite
 *   range, NaN and infinite values replaced by the lowest finite one.
 * Build() says why when nothing can be rendered (GetError()) and what it
 * changed or left out (GetWarnings()); the mapper reports both.
 */
#ifndef vtkHAVSMesh_h
#define vtkHAVSMesh_h

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkNew.h"            // For vtkNew
#include "vtkObject.h"

#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkDataObject;
class vtkHAVSFaceSet;

class VTKHAVSCORE_EXPORT vtkHAVSMesh : public vtkObject
{
public:
  static vtkHAVSMesh* New();
  vtkTypeMacro(vtkHAVSMesh, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Which scalars: vtkAbstractMapper's scalar mode, array access, id, name.
  struct ScalarSelection
  {
    int Mode = 0;
    int AccessMode = 0;
    int Id = -1;
    std::string Name;
    bool operator==(const ScalarSelection& o) const
    {
      return this->Mode == o.Mode && this->AccessMode == o.AccessMode && this->Id == o.Id &&
        this->Name == o.Name;
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
  /// Modified at every Build(), successful or not.
  vtkMTimeType GetBuildTime() const { return this->BuildTime.GetMTime(); }

  /// Why the last Build() failed (empty when it did not).
  const std::string& GetError() const { return this->Error; }
  /// What the last Build() changed or left out (skipped cells, NaN scalars …).
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }

  vtkHAVSFaceSet* GetFaceSet() { return this->Faces; }
  /// Three floats per point: grid coordinates minus GetShift().
  const std::vector<float>& GetPoints() const { return this->Points; }
  /// One per point, in [0, 1] over GetScalarRange().
  const std::vector<float>& GetScalars() const { return this->Scalars; }
  const double* GetShift() const { return this->Shift; }
  /// The points' bounds in model coordinates (shifted).
  const double* GetBounds() const { return this->Bounds; }
  /// The finite range of the scalars rendered.
  const double* GetScalarRange() const { return this->ScalarRange; }
  /// The component rendered, and how many the array has.
  int GetComponent() const { return this->Component; }
  int GetNumberOfComponents() const { return this->NumberOfComponents; }

protected:
  vtkHAVSMesh();
  ~vtkHAVSMesh() override;

private:
  vtkHAVSMesh(const vtkHAVSMesh&) = delete;
  void operator=(const vtkHAVSMesh&) = delete;

  bool Fail(const std::string& why);

  vtkNew<vtkHAVSFaceSet> Faces;
  std::vector<float> Points;
  std::vector<float> Scalars;
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
};

#endif
