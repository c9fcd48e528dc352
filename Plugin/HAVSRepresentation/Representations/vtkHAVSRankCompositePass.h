/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRankCompositePass.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class vtkHAVSRankCompositePass
 * @brief Composites the MPI ranks' HAVS volume images in float, in place of
 * IceT's 8-bit blend.
 *
 * ParaView composites the ranks' images with IceT, in 8 bits: each rank's
 * image is rounded to 8 bits and each "over" truncates, which leaves the
 * parallel image up to 0.55/255 RMSE off the exact one at 8 ranks however
 * exactly each rank draws (issue 44). This pass stands between ParaView's
 * camera pass and its vtkIceTCompositePass. It lets IceT composite as
 * always; then, when every rank's image is one volume with a vtkHAVS mapper
 * alone (nothing else visible) whose mapper kept its float result this frame
 * (vtkHAVSMapperBase::KeepFloatResult), it gathers those premultiplied float
 * images on the rank that displays IceT's tile, composites them front to back
 * in the order of the ranks' kd boxes (the order IceT was given), rounds once
 * to 8 bits, and puts the result in IceT's tile: the image ParaView shows and
 * sends to a client. Otherwise, and in frames ParaView renders without IceT,
 * IceT's image stays, and GetLastFloatComposite() says why.
 *
 * A rank whose volume drew nothing this frame (an empty piece, a piece
 * outside the view that IceT did not ask to draw) gives a transparent image.
 * Every rank takes part in the exchange only after vtkIceTCompositePass's
 * Render, which is collective itself: the exchange runs on the ranks that
 * composited together. A safety check keeps IceT's tile when the float
 * composite differs from it by more than IceT's arithmetic can explain
 * (GetMaximumIceTDifference(), in 1/255), with a warning.
 */
#ifndef vtkHAVSRankCompositePass_h
#define vtkHAVSRankCompositePass_h

#include "vtkHAVSABINamespace.h"          // For VTK_ABI_NAMESPACE_BEGIN
#include "vtkHAVSRepresentationsModule.h" // For export macro
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN
class vtkFloatArray;
class vtkIceTCompositePass;

class VTKHAVSREPRESENTATIONS_EXPORT vtkHAVSRankCompositePass : public vtkRenderPass
{
public:
  static vtkHAVSRankCompositePass* New();
  vtkTypeMacro(vtkHAVSRankCompositePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// ParaView's IceT composite pass this one renders through.
  void SetIceTPass(vtkIceTCompositePass* pass);
  vtkIceTCompositePass* GetIceTPass() const { return this->IceTPass; }
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// What the last frame did: 1 composited in float, 0 kept IceT's 8-bit
  /// image (GetLastReason() says why), -1 no frame yet.
  vtkGetMacro(LastFloatComposite, int);
  /// Why the last frame kept IceT's image ("" when it did not).
  const char* GetLastReason() const { return this->LastReason.c_str(); }
  /// Seconds the last float composite took on this rank (the gather and, on
  /// the displaying rank, the composite).
  vtkGetMacro(LastCompositeSeconds, double);
  /// The largest difference between the float composite and IceT's tile in
  /// the last frame, in 1/255 (the displaying rank; -1 elsewhere).
  vtkGetMacro(LastIceTDifference, int);

  ///@{
  /**
   * The safety check: IceT's tile is kept when the float composite differs
   * from it by more than this (in 1/255; default 16). IceT's rounding and
   * truncation stay within a few levels (measured: 4 at 8 ranks).
   */
  vtkSetMacro(MaximumIceTDifference, int);
  vtkGetMacro(MaximumIceTDifference, int);
  ///@}

protected:
  vtkHAVSRankCompositePass();
  ~vtkHAVSRankCompositePass() override;

private:
  vtkHAVSRankCompositePass(const vtkHAVSRankCompositePass&) = delete;
  void operator=(const vtkHAVSRankCompositePass&) = delete;

  /// 0 when this rank's image can take part (its float image in `image`,
  /// zeros when it drew nothing); a reason code otherwise.
  int RankImage(
    const vtkRenderState* s, unsigned long since, const int size[2], vtkFloatArray* image) const;
  void Composite(const vtkRenderState* s, unsigned long since);

  vtkSmartPointer<vtkIceTCompositePass> IceTPass;
  int LastFloatComposite = -1;
  std::string LastReason;
  double LastCompositeSeconds = 0.0;
  int LastIceTDifference = -1;
  int MaximumIceTDifference = 16;
  bool WarnedDifference = false;
};

VTK_ABI_NAMESPACE_END
#endif
