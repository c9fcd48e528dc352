/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSVTKCompat.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file vtkHAVSVTKCompat.h
 * @brief The GL-free part of vtkHAVS's VTK shim: the VTK calls whose
 * spelling differs between the VTKs vtkHAVS builds with (9.2 on Debian 12,
 * 9.3 on Debian 13, 9.6 on Debian testing), each written once here, so that
 * no other file tests VTK's version. The OpenGL part is vtkHAVSOpenGL.h.
 *
 * - Cell type queries: vtkCellTypes' static ones are deprecated in VTK 9.6
 *   for vtkCellTypeUtilities (VTK >= 9.4).
 * - An unstructured grid's cell types: GetCellTypesArray() is deprecated in
 *   VTK 9.6, and gives nullptr there for a grid made with SetCells(type,
 *   cells), whose GetCellTypes() is a vtkConstantArray (a crash before this
 *   was known); CellTypeBytes converts such an array.
 * - vtkCellArray::Visit is deprecated in VTK 9.6 for Dispatch, which hands
 *   the functor the raw arrays (possibly implicit) instead of the storage
 *   state; vtkHAVS's functors read the storage state, so Visit stays, called
 *   here with the deprecation silenced.
 *
 * Private to vtkHAVS (not installed).
 */
#ifndef vtkHAVSVTKCompat_h
#define vtkHAVSVTKCompat_h

#include "vtkCellArray.h"
#include "vtkCellTypes.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"

#include <utility>

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
#include "vtkCellTypeUtilities.h"
#define VTKHAVS_HAS_CELL_TYPE_UTILITIES 1
#endif

// Silences VTK's deprecation warning around one call of the shim.
#if defined(__GNUC__)
#define VTKHAVS_DEPRECATED_BEGIN                                                                   \
  _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wdeprecated-declarations\"")
#define VTKHAVS_DEPRECATED_END _Pragma("GCC diagnostic pop")
#else
#define VTKHAVS_DEPRECATED_BEGIN
#define VTKHAVS_DEPRECATED_END
#endif

namespace havs_vtk
{
/// The dimension of a cell type (0 to 3).
inline int CellTypeDimension(unsigned char type)
{
#if defined(VTKHAVS_HAS_CELL_TYPE_UTILITIES)
  return vtkCellTypeUtilities::GetDimension(type);
#else
  return vtkCellTypes::GetDimension(type);
#endif
}

/// Whether a cell type is linear.
inline bool IsLinearCellType(unsigned char type)
{
#if defined(VTKHAVS_HAS_CELL_TYPE_UTILITIES)
  return vtkCellTypeUtilities::IsLinear(type) != 0;
#else
  return vtkCellTypes::IsLinear(type) != 0;
#endif
}

/// The VTK class name of a cell type ("UnknownClass" for none).
inline const char* CellTypeClassName(int type)
{
#if defined(VTKHAVS_HAS_CELL_TYPE_UTILITIES)
  return vtkCellTypeUtilities::GetClassNameFromTypeId(type);
#else
  return vtkCellTypes::GetClassNameFromTypeId(type);
#endif
}

/// The grid's cell types array as the grid holds it (VTK 9.6: a grid given
/// one type by SetCells(type, cells) holds a vtkConstantArray; nullptr for a
/// grid without cells): to read through vtkDataArray.
inline vtkDataArray* CellTypeArray(vtkUnstructuredGrid* grid)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
  return grid->GetCellTypes();
#else
  return grid->GetCellTypesArray();
#endif
}

/// The grid's cell types, one byte a cell: the grid's own array where it is
/// one, else (VTK 9.6's constant array, where GetCellTypesArray() gives
/// nullptr) a copy made from it; nullptr for a grid without cells.
inline vtkSmartPointer<vtkUnsignedCharArray> CellTypeBytes(vtkUnstructuredGrid* grid)
{
  vtkDataArray* types = CellTypeArray(grid);
  if (!types)
  {
    return nullptr;
  }
  if (auto* bytes = vtkUnsignedCharArray::FastDownCast(types))
  {
    return bytes;
  }
  auto bytes = vtkSmartPointer<vtkUnsignedCharArray>::New();
  bytes->SetNumberOfTuples(types->GetNumberOfTuples());
  for (vtkIdType i = 0; i < types->GetNumberOfTuples(); ++i)
  {
    bytes->SetValue(i, static_cast<unsigned char>(types->GetComponent(i, 0)));
  }
  return bytes;
}

/// cells->Visit(functor, args...): the functor gets the cell array's storage state.
template <typename Functor, typename... Args>
void VisitCells(vtkCellArray* cells, Functor&& functor, Args&&... args)
{
  VTKHAVS_DEPRECATED_BEGIN
  cells->Visit(std::forward<Functor>(functor), std::forward<Args>(args)...);
  VTKHAVS_DEPRECATED_END
}
}

#endif
