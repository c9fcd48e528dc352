/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSUnstructuredGridVolumeRepresentation.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSUnstructuredGridVolumeRepresentation
 * @brief   ParaView's unstructured-grid volume representation, rendering with HAVS.
 *
 * A vtkUnstructuredGridVolumeRepresentation whose volume mapper is a
 * vtkHAVSVolumeMapper registered as "HAVS" and active by default (the stock
 * mappers stay registered by the SI class). ParaView's data redistribution,
 * ordered compositing, transfer functions and block selection work as for the
 * stock "Volume" representation; the plugin's XML shows it as the
 * "HAVS Volume" representation type.
 *
 * Level of detail: while the user interacts ParaView would swap the volume
 * for its LOD geometry (an outline or a surface); HAVS stays interactive
 * instead, so this representation keeps the volume and renders it with
 * InteractiveKBufferSize entries (default 2) until the still render, which
 * uses the full k.
 *
 * The HAVS settings are forwarded to the mapper on every rank.
 */
#ifndef vtkHAVSUnstructuredGridVolumeRepresentation_h
#define vtkHAVSUnstructuredGridVolumeRepresentation_h

#include "vtkHAVSRepresentationsModule.h" // For export macro
#include "vtkUnstructuredGridVolumeRepresentation.h"

class vtkHAVSVolumeMapper;

class VTKHAVSREPRESENTATIONS_EXPORT vtkHAVSUnstructuredGridVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkHAVSUnstructuredGridVolumeRepresentation* New();
  vtkTypeMacro(
    vtkHAVSUnstructuredGridVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Forwarded to vtkHAVSVolumeMapper (see there).
  void SetHAVSKBufferSize(int k);
  int GetHAVSKBufferSize();
  void SetHAVSEarlyRayTerminationOpacity(double opacity);
  void SetHAVSTableResolution(int resolution);
  void SetHAVSHigherOrderSubdivision(int level);
  void SetHAVSAutomaticTable(int automatic);
  void SetHAVSSkipHiddenCells(int skip);
  void SetHAVSBoundaryMode(int mode);
  void SetHAVSVisibilityOrder(int order);
  void SetHAVSNonConvexMethod(int method);
  void SetHAVSCountOrderViolations(int count);
  void SetHAVSLODStrategy(int strategy);
  ///@}

  /// The order violations of the last frame this rank rendered (counted when
  /// SetHAVSCountOrderViolations is on or while Automatic probes; -1 when not
  /// counted).
  int GetHAVSLastOrderViolations();

  ///@{
  /**
   * HAVS's level of detail while the user interacts (on by default): keep
   * the volume, drawn with the boundary faces and as many of the most
   * important internal faces (vtkHAVSVolumeMapper::SetLevelOfDetail) as fit
   * in InteractiveTargetSeconds, with InteractiveKBufferSize entries; every
   * face when still. Off: ParaView's own LOD (its outline or surface
   * geometry) as for the stock mappers.
   */
  vtkSetMacro(InteractiveLOD, bool);
  vtkGetMacro(InteractiveLOD, bool);
  ///@}

  ///@{
  /// The frame time HAVS aims at while the user interacts (seconds; 0.1 by default).
  vtkSetClampMacro(InteractiveTargetSeconds, double, 0.001, 10.0);
  vtkGetMacro(InteractiveTargetSeconds, double);
  ///@}

  /// The fraction of the internal faces the last frame drew (1: all).
  double GetHAVSLastLODFraction();

  ///@{
  /// k while the user interacts (ParaView's LOD renders); default 2.
  vtkSetClampMacro(InteractiveKBufferSize, int, 1, 64);
  vtkGetMacro(InteractiveKBufferSize, int);
  ///@}

  /// The k of the last frame this rank rendered (0 before one).
  int GetHAVSActiveKBufferSize();

  /**
   * This representation always renders with HAVS: any other name (e.g. a
   * default pushed by an inherited proxy definition) selects HAVS too.
   */
  void SetActiveVolumeMapper(const char* name) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkHAVSUnstructuredGridVolumeRepresentation();
  ~vtkHAVSUnstructuredGridVolumeRepresentation() override;

private:
  vtkHAVSUnstructuredGridVolumeRepresentation(
    const vtkHAVSUnstructuredGridVolumeRepresentation&) = delete;
  void operator=(const vtkHAVSUnstructuredGridVolumeRepresentation&) = delete;

  vtkHAVSVolumeMapper* HAVSMapper;
  int KBufferSize = 2;
  int InteractiveKBufferSize = 2;
  bool InteractiveLOD = true;
  double InteractiveTargetSeconds = 0.1;
};

#endif
