/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewData.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsViewData.h
 * @brief What havs_view opens: a catalogue name or any mesh file VTK reads.
 */
#ifndef havsViewData_h
#define havsViewData_h

#include "vtkSmartPointer.h"

#include <string>

class vtkUnstructuredGrid;

namespace havsview
{
/// Where a mesh comes from, as given on the command line.
struct DataSource
{
  std::string Name;     ///< a vtkHAVSDataSets name, or a file path
  std::string Array;    ///< the scalar array (empty: the reader's or the first)
  std::string Solution; ///< PLOT3D: the q file (empty: none given)
  int Function = 100;   ///< PLOT3D: the scalar function (100 density, 110 pressure)
};

/**
 * The mesh of `source` as tetrahedra with active scalars, or nullptr with
 * `error` set. Names of vtkHAVSDataSets (bluntfin, combustor, gen1M, box …);
 * files: .vtu, .vtk (legacy), PLOT3D (.xyz/.bin with a q file), Exodus
 * (.exo, .e, .ex2, .g; every element block appended).
 */
vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const DataSource& source, std::string& error);

/// A one-line description of what LoadMesh accepts (for --help).
std::string DescribeSources();
}

#endif
