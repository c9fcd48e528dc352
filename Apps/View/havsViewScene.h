/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewScene.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   havsview::Scene
 * @brief   What havs_view shows: the volume, its mapper and settings, the
 *          status line, the transfer-function editor, screenshots.
 *
 * One renderer holds the volume and the status line; the editor's renderer
 * (the bottom strip) is drawn after it. The mappers are made when first chosen and kept, so that
 * switching back finds HAVS with its order and table. Screenshots hide the
 * overlays, render, and write the window's colour as PNG with a text file
 * beside it that holds everything needed to render the same image again
 * (data set, size, camera, transfer functions, mapper, blend mode): the test
 * renders the exact reference from it.
 */
#ifndef havsViewScene_h
#define havsViewScene_h

#include "havsViewTransferFunctionEditor.h"

#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <string>

class vtkAbstractVolumeMapper;
class vtkHAVSVolumeMapper;
class vtkRenderWindow;

namespace havsview
{
class Scene
{
public:
  enum MapperKind
  {
    MapperHAVS = 0,
    MapperCellProjection,
    MapperPT,
    MapperZSweep,
    MapperRayCast,
    MapperTetRayCast, ///< vtkHAVSRayCastMapper
    NumberOfMappers
  };

  Scene();
  ~Scene();

  /// The mesh (tetrahedra, active scalars) and the name it was opened by.
  void SetMesh(vtkUnstructuredGrid* grid, const std::string& name);
  /// Puts the renderers into `window` (two layers).
  void AddToWindow(vtkRenderWindow* window);

  vtkRenderer* GetRenderer() const { return this->Renderer; }
  TransferFunctionEditor& GetEditor() { return this->Editor; }
  vtkVolumeProperty* GetProperty() const { return this->Property; }

  ///@{
  /// The settings the keys change; each returns a line saying what it set.
  std::string SetMapper(int kind);
  std::string NextMapper();
  std::string NextKBufferSize();
  std::string ToggleAutomaticK();
  std::string NextOrder();
  std::string NextBlendMode();
  std::string ToggleLevelOfDetail();
  std::string ToggleIsoSurfacesInComposite();
  std::string ToggleTranslucentPlane();
  std::string ToggleShading();
  std::string ToggleViolationCount();
  std::string NextColorPreset();
  std::string ToggleOverlay();
  std::string ToggleHelp();
  std::string SetKBufferSize(int k);
  std::string SetOrder(const std::string& name);
  ///@}

  /// The mapper in use and its name.
  vtkAbstractVolumeMapper* GetMapper() const;
  std::string GetMapperName() const;

  /// A line under the status line saying what the last key did.
  void SetLastAction(const std::string& text) { this->LastAction = text; }

  /// The status line for the last frame (seconds it took).
  void UpdateStatus(double frameSeconds);

  /**
   * Renders without overlays and writes `path` (PNG, RGB) and `path`.txt (the
   * scene's state); restores the overlays. With `overlay`, the window as it is
   * shown (status line, editor), and no state. False with `error` on failure.
   */
  bool Screenshot(
    vtkRenderWindow* window, const std::string& path, std::string& error, bool overlay = false);

  /// The keys, for the help overlay and --help.
  static std::string KeyHelp();

private:
  Scene(const Scene&) = delete;
  void operator=(const Scene&) = delete;

  vtkAbstractVolumeMapper* MakeMapper(int kind);
  /// The HAVS mapper, made when first needed (its settings live on it).
  vtkHAVSVolumeMapper* GetHAVSMapper();
  /// The blend mode (and the mixed mode) on a mapper: VTK's stay composite for isosurfaces.
  void ApplyBlendMode(vtkAbstractVolumeMapper* mapper);
  /// Two isovalues (30 % and 65 % of the range) when the property has none.
  void EnsureIsoValues();
  /// The level of detail (on or off) on a mapper of the project's.
  void ApplyLevelOfDetail(vtkAbstractVolumeMapper* mapper) const;

  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::string Name;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkTextActor> Help;
  TransferFunctionEditor Editor;
  vtkSmartPointer<vtkAbstractVolumeMapper> Mappers[NumberOfMappers];
  int Mapper = MapperHAVS;
  bool IsoSurfacesInComposite = false; ///< the project's mappers' mixed mode
  bool LevelOfDetail = true; ///< every project mapper's: the reduced image, HAVS's face subset
  int BlendMode = 0;
  bool Overlay = true;
  /// A translucent plane through the mesh's centre, intermixed (vtkHAVSIntermixPass).
  vtkSmartPointer<vtkActor> Plane;
  vtkSmartPointer<vtkRenderPass> Intermix;
  std::string LastAction;
};
}

#endif
