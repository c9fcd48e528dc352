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
 * be depends on the transfer functions: a ramp with a few nodes is
 * represented well by 64^3, a narrow peak needs more than 128^3.
 *
 * Build() builds the candidate resolutions in increasing order (32, 64,
 * 128, ... up to the largest allowed; both axes alike, each capped by its
 * largest) and measures each table's error, and keeps the first within
 * ErrorBound (when none is, the largest). The error falls with the square of
 * the resolution: a size whose error exceeds 6 ErrorBound skips the next one.
 * A rebuild for new functions, range or lengths (a transfer-function edit,
 * issue 45) starts from the last choice instead: kept where it meets the
 * bound, the half size tried only where it is predicted to meet it too (4
 * times the error within the bound), larger sizes as above where it misses.
 * An edit then builds one table, not every size below the choice. A change
 * of the bound, the other settings or the largest sizes searches from the
 * smallest again.
 *
 * The error measured is the one that accumulates along a ray: at ProbeCount
 * segments drawn uniformly over the table's domain (fixed seed), the largest
 * difference over the premultiplied colour and opacity between the table's
 * trilinear look-up (vtkHAVSPreIntegrationTable::Lookup, exactly as the GPU
 * samples it) and the segment integrated adaptively from the property's own
 * functions (vtkHAVSPreIntegrationTable::IntegrateSegment, at most 256
 * sub-steps, Richardson-extrapolated: about 1e-6 on a ramp),
 * per unit distance of the segment's length (ScalarOpacityUnitDistance; at
 * least one length step of the table), averaged. A ray crossing D unit
 * distances of mesh gathers about D times it. The mean, not the largest:
 * the largest errors sit in thin slivers of the domain (segments whose scalar
 * span straddles a kink of the functions within one table cell), which rays
 * rarely meet twice, and a sampled maximum is not a stable measure.
 *
 * The probes' integrals depend on the functions, not on the table: Build()
 * integrates them once and compares every candidate with the same values
 * (again only if a candidate's length axis differs), in parallel
 * (vtkSMPTools), each thread on its own deep copies of the functions (VTK's
 * function objects are not promised to be thread-safe; the copies give the
 * same values to the bit). The 256 probes, sampling the functions through
 * VTK's GetTable (vtkHAVSPreIntegrationTable::IntegrateSegment), take about
 * 1.5 ms on 2 cores for the benchmark's function over the blunt fin's range
 * (4.8 ms one GetValue / GetColor call a scalar); a 64^3 table about 2.7 ms.
 *
 * Calibration (TestHAVSTableResolution; the tests' and the benchmark's ramp):
 * the measure falls with the square of the resolution, 2.1e-4 at 32^3,
 * 5.9e-5 at 64^3, 1.1e-5 at 128^3. On the benchmark's gen1M views (512^2,
 * ramp) 32^3 left pixels off by 0.013, 64^3 by 0.0066, 128^3 by 0.0027
 * (RMSE 0.00080, 0.00075, 0.00074); on the blunt fin, the LOX post and the
 * combustor 64^3 and 128^3 give the same RMSE to 1e-5. The default bound,
 * 1e-4, keeps 64^3 and refuses 32^3 for that ramp.
 */
#ifndef vtkHAVSTableResolution_h
#define vtkHAVSTableResolution_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkTimeStamp.h" // For vtkTimeStamp

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSPreIntegrationTable;
class vtkVolumeProperty;

class VTKHAVSCORE_EXPORT vtkHAVSTableResolution : public vtkObject
{
public:
  static vtkHAVSTableResolution* New();
  vtkTypeMacro(vtkHAVSTableResolution, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The largest mean error per unit distance a chosen table may have (default 1e-4).
  vtkSetClampMacro(ErrorBound, double, 0.0, 1.0);
  vtkGetMacro(ErrorBound, double);

  /// Segments probed per candidate (default 256).
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
   * The error of a built table (the mean over ProbeCount probes of the error
   * per unit distance, as above) against the property it was built from.
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

  /// One probe: its segment and its integral from the functions.
  struct Probe
  {
    double Front, Back, Length, Exact[4];
  };
  /**
   * MeasureError with the probes' integrals kept in `probes` (empty, or
   * integrated for another length axis: integrated again), so that the
   * candidates of one Build() integrate them once.
   */
  double MeasureError(vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int component,
    std::vector<Probe>& probes) const;
  /// Integrates `count` probes from the property's functions, in parallel
  /// (vtkSMPTools) on per-thread deep copies of them.
  static void IntegrateProbes(vtkVolumeProperty* property, int component, Probe* probes, int count);

  double ErrorBound = 1e-4;
  int ProbeCount = 256;
  int SmallestResolution = 32;
  double LastError = 0.0;
  int LastCandidates = 0;
  double LastSeconds = 0.0;
  int BuiltMaxima[2] = { 0, 0 };
  int LastChoice = 0; // the resolution the last Build() kept (0: none yet)
  vtkTimeStamp BuildTime;
};

VTK_ABI_NAMESPACE_END
#endif
