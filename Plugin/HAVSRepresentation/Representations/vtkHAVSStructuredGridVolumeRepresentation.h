/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSStructuredGridVolumeRepresentation.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSStructuredGridVolumeRepresentation
 * @brief   The HAVS volume representation for structured grids.
 *
 * As ParaView's vtkStructuredGridVolumeRepresentation does for its stock
 * mappers: accepts vtkStructuredGrid (and composite data of them); the
 * representation's preprocessor tetrahedralizes it, and HAVS renders it.
 */
#ifndef vtkHAVSStructuredGridVolumeRepresentation_h
#define vtkHAVSStructuredGridVolumeRepresentation_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSRepresentationsModule.h" // For export macro
#include "vtkHAVSUnstructuredGridVolumeRepresentation.h"

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSREPRESENTATIONS_EXPORT vtkHAVSStructuredGridVolumeRepresentation
  : public vtkHAVSUnstructuredGridVolumeRepresentation
{
public:
  static vtkHAVSStructuredGridVolumeRepresentation* New();
  vtkTypeMacro(
    vtkHAVSStructuredGridVolumeRepresentation, vtkHAVSUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkHAVSStructuredGridVolumeRepresentation() = default;
  ~vtkHAVSStructuredGridVolumeRepresentation() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkHAVSStructuredGridVolumeRepresentation(
    const vtkHAVSStructuredGridVolumeRepresentation&) = delete;
  void operator=(const vtkHAVSStructuredGridVolumeRepresentation&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
