/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTableResolution.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSTableResolution
 * @brief   Chooses the cheapest pre-integration table whose error stays within a bound.
 *
 * A smaller table is cheaper to build and, above all, to sample: its texels
 * stay in the caches the draw's look-ups go through (on llvmpipe, a 64^3
 * table instead of 128^3 saves up to a tenth of the draw). How small it may
 * be depends on the transfer functions: a smooth ramp is represented well by
 * 32^3, a sharp peak needs 256^3.
 *
 * Choose() builds the candidate resolutions in increasing order (32, 64,
 * 128, ... up to the largest allowed; both axes alike, each capped by its
 * largest) and measures each table's error: the largest difference, over the
 * premultiplied colour and opacity, between the table's trilinear look-up
 * (vtkHAVSPreIntegrationTable::Lookup, exactly as the GPU samples it) and the
 * segment integrated adaptively from the property's own functions
 * (vtkHAVSPreIntegrationTable::IntegrateSegment, error <= 1e-6), at
 * ProbeCount segments. The probes lie at the centres of table cells, where
 * trilinear interpolation errs most, drawn at random (fixed seed) from the
 * cells whose corners differ most and from all cells. The first candidate
 * within ErrorBound wins; when none is, the largest.
 *
 * The error is per segment; along a ray the segments' errors are attenuated
 * and partly cancel. The default bound, 2e-3, is what the 128^3 table meets on
 * the benchmark's and the tests' transfer functions, whose images are exact
 * (MISSION.md) with it.
 */
#ifndef vtkHAVSTableResolution_h
#define vtkHAVSTableResolution_h

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkTimeStamp.h" // For vtkTimeStamp

class vtkHAVSPreIntegrationTable;
class vtkVolumeProperty;

class VTKHAVSCORE_EXPORT vtkHAVSTableResolution : public vtkObject
{
public:
  static vtkHAVSTableResolution* New();
  vtkTypeMacro(vtkHAVSTableResolution, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The largest error per segment a chosen table may have (default 2e-3).
  vtkSetClampMacro(ErrorBound, double, 0.0, 1.0);
  vtkGetMacro(ErrorBound, double);

  /// Segments probed per candidate (default 384).
  vtkSetClampMacro(ProbeCount, int, 1, 1 << 20);
  vtkGetMacro(ProbeCount, int);

  /// The smallest candidate resolution (default 32).
  vtkSetClampMacro(SmallestResolution, int, 2, 1024);
  vtkGetMacro(SmallestResolution, int);

  /**
   * Builds into `table` the cheapest table within ErrorBound, at most
   * maxScalarResolution x maxScalarResolution x maxLengthResolution, for
   * `component` of `property` over `scalarRange`, lengths up to `maxLength`.
   * Returns false where vtkHAVSPreIntegrationTable::Build does (the table is
   * then all zero).
   */
  bool Build(vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int component,
    const double scalarRange[2], double maxLength, int maxScalarResolution,
    int maxLengthResolution);

  /**
   * True when Build() would give another table: `table` needs a rebuild at
   * its present resolution (property, range, length), or the largest
   * resolutions or this object's settings changed since the last Build().
   */
  bool NeedsRebuild(const vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property,
    int component, const double scalarRange[2], double maxLength, int maxScalarResolution,
    int maxLengthResolution) const;

  /**
   * The error of a built table (the largest over ProbeCount probes, as
   * above) against the property it was built from.
   */
  double MeasureError(
    vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int component) const;

  ///@{
  /// The last Build(): the measured error of the table kept, the candidates
  /// tried, and the seconds it took (builds and probes).
  vtkGetMacro(LastError, double);
  vtkGetMacro(LastCandidates, int);
  vtkGetMacro(LastSeconds, double);
  ///@}

protected:
  vtkHAVSTableResolution() = default;
  ~vtkHAVSTableResolution() override = default;

private:
  vtkHAVSTableResolution(const vtkHAVSTableResolution&) = delete;
  void operator=(const vtkHAVSTableResolution&) = delete;

  double ErrorBound = 2e-3;
  int ProbeCount = 384;
  int SmallestResolution = 32;
  double LastError = 0.0;
  int LastCandidates = 0;
  double LastSeconds = 0.0;
  int BuiltMaxima[2] = { 0, 0 };
  vtkTimeStamp BuildTime;
};

#endif
