/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSorter.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFaceSorter
 * @brief   Per-frame front-to-back centroid sort of a vtkHAVSFaceSet.
 *
 * HAVS's per-frame sort (Callahan, Ikits, Comba and Silva 2005). The key of a
 * face is its centroid's squared world-space distance to the eye
 * (perspective) or its depth along the direction of projection (parallel),
 * after the volume's model-to-world matrix; keys are computed in parallel and
 * sorted with vtkHAVSRadixSorter. The sort is reused (Sort() returns false)
 * while the face set's build, the matrix, the eye, the direction, the
 * projection and this object's settings are all unchanged.
 */
#ifndef vtkHAVSFaceSorter_h
#define vtkHAVSFaceSorter_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkNew.h"            // For vtkNew
#include "vtkObject.h"

#include <array>   // For std::array
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSFaceSet;
class vtkHAVSRadixSorter;

class VTKHAVSCORE_EXPORT vtkHAVSFaceSorter : public vtkObject
{
public:
  static vtkHAVSFaceSorter* New();
  vtkTypeMacro(vtkHAVSFaceSorter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Sorts the faces nearest first. `modelToWorld` is a row-major 4x4 matrix
   * (vtkMatrix4x4 element order), affine: its last row is not used. The key
   * of a face is the squared distance from the eye to its world-space
   * centroid (perspective), or the centroid's offset from the eye along the
   * direction of projection (parallel). Returns true when it sorted, false
   * when the previous order still holds (or, with an error, for a null face
   * set).
   */
  bool Sort(vtkHAVSFaceSet* faces, const double modelToWorld[16], const double eyeWorld[3],
    const double directionOfProjectionWorld[3], bool parallelProjection);

  /// Forces the next Sort() to sort.
  void Invalidate() { this->Valid = false; }

  /// Face indices, nearest first.
  const std::vector<uint32_t>& GetOrder() const { return this->Order; }

  /**
   * Sort only these faces (indices into the face set, ascending), e.g. those
   * of the cells a frame can see; nullptr (the default) sorts every face.
   * The faces left out get no key and are not in GetOrder(). `version`
   * changes whenever the list does (Sort() sorts again then). The radix sort
   * is stable, so the order equals the full order with the other faces taken
   * out. The list is not copied: it must outlive the next Sort().
   */
  void SetFaceSubset(const std::vector<uint32_t>* faces, vtkMTimeType version);
  /// Faces in the last order (the subset's size, or every face).
  vtkIdType GetNumberOfSortedFaces() const { return static_cast<vtkIdType>(this->Order.size()); }

  ///@{
  /// Wall time of the last real sort, and how many real sorts ran.
  vtkGetMacro(LastSortSeconds, double);
  vtkGetMacro(NumberOfSorts, vtkIdType);
  ///@}

  ///@{
  /**
   * Test aid: after sorting, reverse the order inside every block of this many
   * consecutive faces (1, the default, leaves it alone), so that each face ends
   * at most BlockReversal - 1 places from its sorted position. Used to feed the
   * k-buffer a nearly sorted stream of known disorder.
   */
  vtkSetClampMacro(BlockReversal, int, 1, 1 << 20);
  vtkGetMacro(BlockReversal, int);
  ///@}

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSFaceSorter();
  ~vtkHAVSFaceSorter() override;

private:
  vtkHAVSFaceSorter(const vtkHAVSFaceSorter&) = delete;
  void operator=(const vtkHAVSFaceSorter&) = delete;

  vtkNew<vtkHAVSRadixSorter> RadixSorter;
  std::vector<float> Keys;
  std::vector<uint32_t> Order;
  std::vector<uint32_t> SubsetOrder;
  const std::vector<uint32_t>* Subset = nullptr;
  vtkMTimeType SubsetVersion = 0;
  vtkMTimeType LastSubsetVersion = 0;
  bool Valid = false;
  vtkMTimeType LastFaceBuildTime = 0;
  vtkMTimeType LastSortMTime = 0;
  std::array<double, 16> LastMatrix{};
  std::array<double, 3> LastEye{};
  std::array<double, 3> LastDirection{};
  bool LastParallel = false;
  double LastSortSeconds = 0.0;
  vtkIdType NumberOfSorts = 0;
  int BlockReversal = 1;
};

VTK_ABI_NAMESPACE_END
#endif
