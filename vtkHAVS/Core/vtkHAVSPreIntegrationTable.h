/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPreIntegrationTable.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSPreIntegrationTable
 * @brief   The 3D pre-integrated transfer-function table the k-buffer samples.
 *
 * Pre-integration (Röttger, Kraus and Ertl 2000; Engel, Kraus and Ertl 2001)
 * as HAVS uses it (Callahan, Ikits, Comba and Silva 2005). Entry (f, b, l)
 * holds the premultiplied colour and opacity of a ray segment
 * of world length L_l = LengthAt(l / (NL - 1)) whose scalar goes linearly
 * from s_f to s_b (s_i = range[0] + i / (NS - 1) * (range[1] - range[0])),
 * under the optical model of VTK's unstructured-grid integrators:
 * extinction tau(s) = opacity(s) / ScalarOpacityUnitDistance, emission
 * colour(s) * tau(s), attenuated front to back. Layout: RGBA floats, index
 * ((l * NS + b) * NS + f) * 4 (front scalar fastest).
 *
 * The functions are evaluated from the property itself (GetValue/GetColor:
 * midpoints, sharpness, colour spaces count), first sampled serially on a fine
 * grid of (NS - 1) * SubdivisionsPerInterval + 1 scalars, to which the
 * functions' own nodes are added (so a spike narrower than a sub-step is
 * integrated, not stepped over). Each entry is then
 * integrated over the fine samples the segment crosses, tau and colour linear
 * in each sub-step, the sub-step's attenuation exact for its mean extinction
 * and its colour the mean of its ends' colours weighted by where the light
 * they emit is seen from (exact for an opaque sub-step: its front colour):
 * a second-order quadrature whose error shrinks with the square of
 * SubdivisionsPerInterval, and holds for long, optically thick segments
 * (issue 20). ExactIntegration integrates each entry adaptively
 * from the functions instead (IntegrateSegment, error <= 1e-6; slow).
 *
 * The quadrature is built by windowed composites (issue 45): for a segment
 * from table scalar f to b, j = |b - f| intervals long, of length L, each
 * sub-step's share of L is its scalar span times (NS - 1) / j, the same in
 * every segment of that j and L. So per (j, direction, length) the
 * sub-steps are composited once, then each table interval (its sub-steps,
 * front to back), and every entry of that j is the composite of j
 * consecutive intervals, taken as a sliding window (each block of j
 * intervals' prefix and suffix composites; an entry is one suffix over one
 * prefix). The entry is the same front-to-back composite of the same
 * sub-steps as integrating it alone, in another association: O(NS^2 NL)
 * compositing operations and O(NS NL (NS SubdivisionsPerInterval)) sub-steps,
 * instead of O(NS^3 NL SubdivisionsPerInterval) sub-steps. On the linear
 * length axis a sub-step's share depends on j and l only through l / j: the
 * interval composites of a coprime (j, l) serve every multiple (q j, q l),
 * so they are computed for about 61 % of the pairs. The sub-steps' weights
 * are computed in one branch-free, vectorized run per (j, l) before their
 * intervals are composited (an AVX2 clone on x86-64). Each j, both
 * directions and its multiples, is a task run in parallel (vtkSMPTools).
 * (Issue 45: a 64^3 table for the benchmark's function in 2.7 ms on 2 cores,
 * 7.1 ms before these three changes.)
 *
 * The functions are evaluated through VTK's GetTable over runs of evenly
 * spaced scalars (the additive blend's function, IntegrateSegment's
 * sub-steps), one pass over their nodes each, rather than one GetValue /
 * GetColor call a scalar (most of the error probes' cost; the same values
 * up to the rounding of the scalars). A colour function on a logarithmic
 * scale or in indexed lookup is evaluated one scalar at a time.
 *
 * The length axis is linear (L = u MaxLength) unless the longest segment
 * spans many optical lengths (MaxLength * tau_max > 16, tau_max the largest
 * extinction of the functions: a mesh whose longest cells are far longer
 * than the transfer function's scale, e.g. 1e6 times longer than wide, or a
 * nearly opaque function). Then it is logarithmic, u = log(1 + a L) /
 * log(1 + a MaxLength) with a = 4 tau_max: uniform steps in u resolve the
 * lengths over which the opacity changes, however long the longest segment
 * (a linear axis of 128 steps over 3e6 would put 2.4e4 in its first step).
 */
#ifndef vtkHAVSPreIntegrationTable_h
#define vtkHAVSPreIntegrationTable_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCellOptics.h" // For vtkNew<vtkHAVSCellOptics>
#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkNew.h"            // For vtkNew
#include "vtkObject.h"

#include <cstddef>    // For size_t
#include <functional> // For std::function
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkVolumeProperty;

class VTKHAVSCORE_EXPORT vtkHAVSPreIntegrationTable : public vtkObject
{
public:
  static vtkHAVSPreIntegrationTable* New();
  vtkTypeMacro(vtkHAVSPreIntegrationTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Table size along the front and back scalar axes (default 128).
  vtkSetClampMacro(ScalarResolution, int, 2, 1024);
  vtkGetMacro(ScalarResolution, int);
  ///@}
  ///@{
  /// Table size along the length axis (default 128).
  vtkSetClampMacro(LengthResolution, int, 2, 1024);
  vtkGetMacro(LengthResolution, int);
  ///@}
  ///@{
  /// Quadrature sub-steps per table scalar interval a segment crosses (default 4).
  vtkSetClampMacro(SubdivisionsPerInterval, int, 1, 64);
  vtkGetMacro(SubdivisionsPerInterval, int);
  ///@}
  ///@{
  /// Integrate every entry adaptively to 1e-6 (slow; for accuracy studies).
  vtkSetMacro(ExactIntegration, bool);
  vtkGetMacro(ExactIntegration, bool);
  ///@}

  /**
   * Builds the table for `component` of `property` over `scalarRange`, lengths
   * up to `maxLength`. Returns false (error) for a null property, a NaN range,
   * a unit distance <= 0; the table is then all zero.
   */
  bool Build(
    vtkVolumeProperty* property, int component, const double scalarRange[2], double maxLength);

  /**
   * True when Build would produce a different table: other inputs, or the
   * property, its functions or these settings modified since the last build.
   */
  bool NeedsRebuild(vtkVolumeProperty* property, int component, const double scalarRange[2],
    double maxLength) const;

  const float* GetTable() const { return this->Table.data(); }
  /**
   * Cell scalars: the functions at each distinct cell value, which their
   * segments read instead of the table's diagonal (built beside the table by
   * vtkHAVSMapperInputs::PrepareTable; empty for point scalars).
   */
  vtkHAVSCellOptics* GetCellOptics() { return this->CellOptics; }
  /// The resolutions the table was last built with (GetTable()'s layout:
  /// RGBA at ((length * n + back) * n + front), n the scalar resolution).
  int GetBuiltScalarResolution() const { return this->BuiltScalarResolution; }
  int GetBuiltLengthResolution() const { return this->BuiltLengthResolution; }
  vtkGetMacro(MaxLength, double);
  /// The length axis' scale a (0: linear); see the class description.
  vtkGetMacro(LengthLogScale, double);
  /// The length axis' coordinate u in [0, 1] of a segment length (clamped),
  /// and its inverse, as the table was built.
  double LengthCoordinate(double length) const;
  double LengthAt(double u) const;
  const double* GetScalarRange() const { return this->ScalarRange; }
  vtkGetMacro(LastBuildSeconds, double);

  /**
   * The 1D transfer function at the ScalarResolution nodes: RGBA = colour,
   * opacity (for maximum / minimum intensity).
   */
  const std::vector<float>& GetTransferFunction1D() const { return this->TransferFunction1D; }

  /// Nodes of GetAdditive1D().
  static constexpr int AdditiveResolution = 1024;

  /**
   * For VTK's additive blend (order-independent: the ray's value is the
   * integral of tau(s) s along it, s normalized to [0, 1], clamped to 1): at
   * AdditiveResolution evenly spaced normalized scalars, pairs (g, G) of
   * g(s) = tau(s) s and its integral from 0, exact for g linear between the
   * nodes. A segment's value is its length times the mean of g over
   * [sf, sb]: (G(sb) - G(sf)) / (sb - sf).
   */
  const std::vector<float>& GetAdditive1D() const { return this->Additive1D; }

  /**
   * The table's value for a segment, trilinear between nodes exactly as the
   * GPU samples it (clamped at the edges).
   */
  void Lookup(double sf, double sb, double length, double rgba[4]) const;

  /**
   * The optical model at scalar s: extinction tau = opacity(s) /
   * ScalarOpacityUnitDistance (>= 0) and colour (grey or RGB), as every entry
   * is integrated from (vtkHAVSCellOptics evaluates cell values with it).
   */
  static void EvaluateOptics(
    vtkVolumeProperty* property, int component, double s, double& tau, double color[3]);
  /// The colour alone at scalar s: the grey function's value thrice (one
  /// colour channel) or the RGB function's colour.
  static void EvaluateColor(vtkVolumeProperty* property, int component, double s, double color[3]);
  /**
   * Appends the scalars of the nodes of `property`'s opacity and colour (or
   * grey) functions for `component`: where their pieces meet.
   */
  static void GetFunctionNodes(
    vtkVolumeProperty* property, int component, std::vector<double>& nodes);

  /**
   * The table's own quadrature of one segment: n uniform sub-steps from the
   * functions, each composited as the table's are. Where the functions' nodes
   * lie on the table's fine grid, entry (f, b, l) equals it with
   * n = |b - f| SubdivisionsPerInterval (n = 1 where f == b).
   */
  static void IntegrateSubSteps(vtkVolumeProperty* property, int component, double sf, double sb,
    double length, int n, double rgba[4]);

  /**
   * Double-precision reference: the segment integrated adaptively from the
   * property's functions to an absolute error <= 1e-6 (sub-steps doubled up
   * to maximumSteps; a smaller one bounds the cost where the functions have
   * many kinks, at some accuracy).
   */
  static void IntegrateSegment(vtkVolumeProperty* property, int component, double sf, double sb,
    double length, double rgba[4], int maximumSteps = 1 << 16);

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

  /**
   * What the windowed quadrature is computed from (issue 45: the table built
   * elsewhere, e.g. on the GPU by vtkHAVSGLTableBuilder): the fine samples'
   * optics, the sub-steps' extinction integrals, where each table scalar lies
   * among the samples and each length layer's segment length. Entry (f, b, l),
   * f != b, composites the sub-steps between TableSample[f] and TableSample[b]
   * front to back (from f's side), sub-step k of optical depth
   * StepDepth[k] L_l (NS - 1) / |b - f| with its ends' optics weighted as
   * CompositeStep does; the diagonal is one sub-step of the optics at f of
   * depth tau L_l.
   */
  struct Quadrature
  {
    int ScalarResolution = 0;
    int LengthResolution = 0;
    std::vector<float> Samples;     ///< per fine sample: tau, red, green, blue
    std::vector<float> StepDepth;   ///< per sub-step k (samples k, k + 1): tau's integral over it
    std::vector<int> TableSample;   ///< per table scalar: its fine sample
    std::vector<float> LayerLength; ///< per length layer: the segment length L_l (L_0 = 0)
  };
  /**
   * A builder of every entry of the table (GetTable()'s layout, length 0
   * included) from the quadrature's inputs; false when it could not (the
   * table is then built here). Build() calls it instead of its own windowed
   * composites (not with ExactIntegration). Setting it changes no table.
   */
  using EntryBuilder = std::function<bool(const Quadrature&, float* table)>;
  void SetEntryBuilder(EntryBuilder builder) { this->Builder = std::move(builder); }
  /// Whether the last Build() had its entries built by the EntryBuilder.
  bool GetLastBuiltByEntryBuilder() const { return this->LastBuiltByEntryBuilder; }

protected:
  vtkHAVSPreIntegrationTable() = default;
  ~vtkHAVSPreIntegrationTable() override = default;

private:
  vtkHAVSPreIntegrationTable(const vtkHAVSPreIntegrationTable&) = delete;
  void operator=(const vtkHAVSPreIntegrationTable&) = delete;

  /// An all-zero table of the set size (lengthZeroOnly and the size
  /// unchanged: only the entries of length 0, for Build() to write the rest).
  void Zero(bool lengthZeroOnly = false);
  vtkNew<vtkHAVSCellOptics> CellOptics;

  int ScalarResolution = 128;
  int LengthResolution = 128;
  int SubdivisionsPerInterval = 4;
  bool ExactIntegration = false;

  std::vector<float> Table;
  std::vector<float> TransferFunction1D;
  std::vector<float> Additive1D;
  double ScalarRange[2] = { 0.0, 1.0 };
  double MaxLength = 0.0;
  double LengthLogScale = 0.0;
  int Component = 0;
  int BuiltScalarResolution = 0;
  int BuiltLengthResolution = 0;
  vtkVolumeProperty* BuiltProperty = nullptr; // identity only, never dereferenced
  vtkTimeStamp BuildTime;
  double LastBuildSeconds = 0.0;
  EntryBuilder Builder;
  bool LastBuiltByEntryBuilder = false;
};

VTK_ABI_NAMESPACE_END
#endif
