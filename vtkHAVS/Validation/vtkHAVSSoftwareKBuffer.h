/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSSoftwareKBuffer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSSoftwareKBuffer
 * @brief   The GPU k-buffer run on the CPU, and the k-requirement analysis.
 *
 * The k-requirement analysis of Callahan 2005 (section 4.3.2, Table 4.2).
 * Each pixel's fragments (from vtkHAVSReferenceRenderer: exact ray–face
 * hits at the pixel centre) are put in the mapper's draw order (the face
 * order of its centroid sort) and fed through a k-entry buffer exactly as the
 * GPU does it (see vtkHAVSKBufferLib.glsl: the front plus k - 1 waiting
 * fragments; a fragment fills an empty slot, else the nearest of the waiting
 * ones and the newcomer leaves and the segment from the front to it is
 * composited from the pre-integrated table; the rest leaves in order at the
 * end). Render() gives the image HAVS must produce for that k.
 *
 * RequiredK() is the smallest k at which that buffer lets a pixel's
 * fragments leave in depth order (MISSION.md's definition): the image is then
 * exact. Analyze() gives, per pixel, the required k and the totals of the
 * thesis' Table 4.2 (fragments, longest list, max k, pixels needing k > 2 and
 * k > 6), and paints the required-k image (green <= 2, yellow <= 6, red > 6).
 */
#ifndef vtkHAVSSoftwareKBuffer_h
#define vtkHAVSSoftwareKBuffer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSValidationModule.h" // For export macro
#include "vtkNew.h"                  // For vtkNew
#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkFloatArray;
class vtkHAVSPreIntegrationTable;
class vtkHAVSReferenceRenderer;
class vtkIntArray;
class vtkUnsignedCharArray;

class VTKHAVSVALIDATION_EXPORT vtkHAVSSoftwareKBuffer : public vtkObject
{
public:
  static vtkHAVSSoftwareKBuffer* New();
  vtkTypeMacro(vtkHAVSSoftwareKBuffer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The smallest k (>= 1) at which the k-buffer outputs these distances,
   * given in draw order, sorted (ties count as sorted).
   */
  static int RequiredK(const double* distances, int n);

  /**
   * The draw order: face indices, first drawn first (e.g. the mapper's
   * vtkHAVSFaceSorter::GetOrder()).
   */
  void SetFaceOrder(const std::vector<uint32_t>& order);

  /**
   * The image of the k-buffer with k entries (premultiplied RGBA, bottom row
   * first) for the fragments of `fragments` (ComputeFragments done) and the
   * table of the mapper. Early ray termination at `terminationOpacity`.
   */
  bool Render(vtkHAVSReferenceRenderer* fragments, vtkHAVSPreIntegrationTable* table, int k,
    double terminationOpacity, vtkFloatArray* image);

  /**
   * Required k of every pixel (0 for an empty pixel) into `requiredK` and the
   * totals below; `colours` (optional) gets the RGB required-k image.
   */
  bool Analyze(
    vtkHAVSReferenceRenderer* fragments, vtkIntArray* requiredK, vtkUnsignedCharArray* colours);

  ///@{
  /// Totals of the last Analyze().
  vtkGetMacro(NumberOfFragments, vtkIdType);
  vtkGetMacro(LongestList, int);
  vtkGetMacro(MaximumRequiredK, int);
  vtkGetMacro(PixelsOverK2, vtkIdType);
  vtkGetMacro(PixelsOverK6, vtkIdType);
  vtkGetMacro(PixelsOverK14, vtkIdType);
  ///@}

protected:
  vtkHAVSSoftwareKBuffer() = default;
  ~vtkHAVSSoftwareKBuffer() override = default;

private:
  vtkHAVSSoftwareKBuffer(const vtkHAVSSoftwareKBuffer&) = delete;
  void operator=(const vtkHAVSSoftwareKBuffer&) = delete;

  std::vector<uint32_t> DrawRank; // face -> position in the draw order
  vtkIdType NumberOfFragments = 0;
  int LongestList = 0;
  int MaximumRequiredK = 0;
  vtkIdType PixelsOverK2 = 0;
  vtkIdType PixelsOverK6 = 0;
  vtkIdType PixelsOverK14 = 0;
};

VTK_ABI_NAMESPACE_END
#endif
