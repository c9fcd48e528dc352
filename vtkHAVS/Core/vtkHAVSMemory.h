/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMemory.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSMemory.h
 * @brief Where a mapper's bytes are: the parts of its memory ledger.
 *
 * Each class that holds per-cell or per-face arrays reports them with
 * GetMemoryBytes() (the arrays' capacities: what the allocator holds for
 * them); vtkHAVSMapperBase::GetMemoryParts() lists the parts of a mapper,
 * the graphics layer's buffers among them (on llvmpipe those live in host
 * memory too). The benchmark's scale section prints them per tetrahedron.
 */
#ifndef vtkHAVSMemory_h
#define vtkHAVSMemory_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include <cstddef> // For size_t
#include <string>  // For std::string
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

namespace vtkHAVSMemory
{
/// The bytes the vectors hold (their capacities).
template <class... Vectors>
size_t Bytes(const Vectors&... vectors)
{
  return (size_t{ 0 } + ... + (vectors.capacity() * sizeof(typename Vectors::value_type)));
}

/// One part of a mapper's memory.
struct Part
{
  std::string Name; ///< what it is ("mesh: faces", "order: MPVO", "GPU buffers", ...)
  size_t Bytes = 0;
};

/// The bytes of all the parts.
inline size_t Sum(const std::vector<Part>& parts)
{
  size_t bytes = 0;
  for (const Part& part : parts)
  {
    bytes += part.Bytes;
  }
  return bytes;
}
}

VTK_ABI_NAMESPACE_END
#endif
