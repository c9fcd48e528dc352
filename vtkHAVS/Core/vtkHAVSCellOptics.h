/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellOptics.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSCellOptics
 * @brief   The transfer function at each distinct cell value (cell scalars).
 *
 * With cell scalars the scalar is constant in a cell, and a segment of length
 * L in a cell of value s has the closed form of the emission-absorption model
 * (the one vtkHAVSPreIntegrationTable integrates): opacity a = 1 - exp(-tau(s)
 * L), premultiplied colour colour(s) a. What the segment needs is the transfer
 * function at s itself, not the table's diagonal (s, s), which interpolates
 * between the table's scalar nodes and so misses a spike of the function
 * narrower than a node spacing at a cell's value (issue 20).
 *
 * vtkHAVSMesh gives each distinct cell value, sorted, an index, and the GPU
 * passes carry a cell's index as its scalar code, CodeOf(index) = index *
 * 2^-CodeBits: exact in a float, also with the boundary tags (+ 2, + 4) of the
 * k-buffer added, and ordered as the values are (a maximum of codes is the
 * code of the maximum). This class evaluates the property's functions at each
 * value (GetValue/GetColor: midpoints, sharpness, colour spaces count) into
 * 8 floats per value, read by texelFetch from a buffer texture:
 * (r, g, b, tau) and (normalized s, opacity, tau s, 0), tau = opacity /
 * ScalarOpacityUnitDistance.
 */

#ifndef vtkHAVSCellOptics_h
#define vtkHAVSCellOptics_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkVolumeProperty;

class VTKHAVSCORE_EXPORT vtkHAVSCellOptics : public vtkObject
{
public:
  static vtkHAVSCellOptics* New();
  vtkTypeMacro(vtkHAVSCellOptics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Bits of a value index in a code: at most 2^CodeBits distinct values.
  static constexpr int CodeBits = 21;
  static constexpr uint32_t MaximumValues = 1u << CodeBits;
  /// The scalar code of value index `index` (< MaximumValues).
  static float CodeOf(uint32_t index);
  /// Floats per value in GetOptics().
  static constexpr int FloatsPerValue = 8;

  /**
   * Evaluates `property`'s functions for `component` at `values` (sorted
   * ascending, finite), normalized over `scalarRange`; `valuesVersion` says
   * which values these are (NeedsRebuild). Returns false (error; no values
   * kept) for a null property or a unit distance <= 0.
   */
  bool Build(vtkVolumeProperty* property, int component, const std::vector<double>& values,
    const double scalarRange[2], vtkMTimeType valuesVersion);
  /// True when Build would give other optics: other values or property, or
  /// the property or its functions modified since.
  bool NeedsRebuild(vtkVolumeProperty* property, int component, vtkMTimeType valuesVersion) const;
  /// No values (point scalars).
  void Clear();

  const std::vector<float>& GetOptics() const { return this->Optics; }
  size_t GetNumberOfValues() const { return this->Optics.size() / FloatsPerValue; }
  vtkGetMacro(LastBuildSeconds, double);

protected:
  vtkHAVSCellOptics() = default;
  ~vtkHAVSCellOptics() override = default;

private:
  vtkHAVSCellOptics(const vtkHAVSCellOptics&) = delete;
  void operator=(const vtkHAVSCellOptics&) = delete;

  std::vector<float> Optics;
  vtkVolumeProperty* BuiltProperty = nullptr; // compared, never dereferenced
  int Component = -1;
  vtkMTimeType ValuesVersion = 0;
  vtkTimeStamp BuildTime;
  double LastBuildSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif
