/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMapperInputs.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSMapperInputs.h"

#include "vtkHAVSCellOptics.h"

#include "vtkHAVSFaceSet.h"
#include "vtkHAVSMesh.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSTableResolution.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkAlgorithm.h"
#include "vtkCompositeDataSet.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPiecewiseFunction.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

VTK_ABI_NAMESPACE_BEGIN

namespace
{
bool IsConstantOne(vtkPiecewiseFunction* f)
{
  if (!f)
  {
    return true;
  }
  double node[4];
  for (int i = 0; i < f->GetSize(); ++i)
  {
    f->GetNodeValue(i, node);
    if (node[1] != 1.0)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
int vtkHAVSMapperInputs::FillInputPortInformation(vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperInputs::GetCompositeInputBounds(vtkAbstractVolumeMapper* mapper, double bounds[6])
{
  if (!vtkCompositeDataSet::SafeDownCast(mapper->GetDataObjectInput()))
  {
    return false;
  }
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
  }
  auto* blocks = vtkCompositeDataSet::SafeDownCast(mapper->GetDataObjectInput());
  if (!blocks)
  {
    return false;
  }
  blocks->GetBounds(bounds);
  return true;
}

//------------------------------------------------------------------------------
vtkHAVSMapperInputs::MeshState vtkHAVSMapperInputs::PrepareMesh(vtkAbstractVolumeMapper* mapper,
  vtkVolume* volume, vtkHAVSMesh* mesh, const char* mapperName, const WarnOnce& warnOnce,
  int vectorMode, int vectorComponent, int higherOrderSubdivision)
{
  vtkHAVSMesh::ScalarSelection selection;
  selection.HigherOrderSubdivision = higherOrderSubdivision;
  selection.VectorMode = vectorMode;
  selection.VectorComponent = vectorComponent;
  selection.Mode = mapper->GetScalarMode();
  selection.AccessMode = mapper->GetArrayAccessMode();
  selection.Id = mapper->GetArrayId();
  selection.Name = mapper->GetArrayName() ? mapper->GetArrayName() : "";
  vtkDataObject* input = mapper->GetDataObjectInput();
  if (!input)
  {
    vtkErrorWithObjectMacro(mapper, "No input.");
    return MeshFailed;
  }
  if (!mesh->NeedsBuild(input, selection))
  {
    return mesh->IsValid() ? MeshUnchanged : MeshFailed;
  }
  const bool built =
    mesh->Build(input, selection, [mapper](double p) { mapper->UpdateProgress(p); });
  for (const std::string& warning : mesh->GetWarnings())
  {
    vtkWarningWithObjectMacro(mapper, << warning);
  }
  if (!built)
  {
    vtkErrorWithObjectMacro(mapper, << mesh->GetError());
    return MeshFailed;
  }
  const int components = mesh->GetNumberOfComponents();
  if (components > 1 && vectorMode == vtkHAVSMesh::VectorModeDisabled)
  {
    warnOnce(WarnComponents,
      "The scalars have " + std::to_string(components) + " components" +
        (volume->GetProperty()->GetIndependentComponents() ? " (independent)" : " (dependent)") +
        "; " + mapperName +
        " renders the first one only (SetVectorMode: the magnitude or another component).");
  }
  switch (mesh->GetLastUpdate())
  {
    case vtkHAVSMesh::UpdateScalars:
      return MeshScalarsUpdated;
    case vtkHAVSMesh::UpdateNone: // the same mesh and scalars in another data object
      return MeshUnchanged;
    default:
      return MeshRebuilt;
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperInputs::PrepareTable(vtkAbstractVolumeMapper* mapper, vtkVolume* volume,
  vtkHAVSMesh* mesh, vtkHAVSPreIntegrationTable* table, int scalarResolution, int lengthResolution,
  const char* mapperName, const WarnOnce& warnOnce, bool* rebuilt,
  vtkHAVSTableResolution* automatic, double longestSegment)
{
  *rebuilt = false;
  vtkVolumeProperty* property = volume->GetProperty();
  const int component = mesh->GetComponent();
  if (property->GetShade(component))
  {
    warnOnce(WarnShading,
      std::string("Shading is not supported by ") + mapperName +
        " for the volume; the volume is unshaded (isosurfaces, of the isosurface blend or "
        "IsoSurfacesInComposite, are lit).");
  }
  if (!property->GetDisableGradientOpacity(component) && property->HasGradientOpacity(component) &&
    !IsConstantOne(property->GetGradientOpacity(component)))
  {
    warnOnce(WarnGradient,
      std::string("Gradient opacity is not supported by ") + mapperName + "; it is ignored.");
  }

  // The longest segment inside one tetrahedron is its longest edge; in world
  // space after the volume's matrix, at most that times the largest stretch.
  vtkMatrix4x4* m = volume->GetMatrix();
  double stretch = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double column[3] = { m->GetElement(0, c), m->GetElement(1, c), m->GetElement(2, c) };
    stretch = std::max(stretch, vtkMath::Norm(column));
  }
  const double longest =
    longestSegment > 0.0 ? longestSegment : mesh->GetFaceSet()->GetLongestEdge();
  const double maxLength = std::max(longest * stretch, 1e-30);

  const double* range = mesh->GetScalarRange();
  if (!automatic)
  {
    table->SetScalarResolution(scalarResolution);
    table->SetLengthResolution(lengthResolution);
  }
  if (automatic ? automatic->NeedsRebuild(table, property, component, range, maxLength,
                    scalarResolution, lengthResolution)
                : table->NeedsRebuild(property, component, range, maxLength))
  {
    mapper->UpdateProgress(0.0);
    if (automatic ? !automatic->Build(table, property, component, range, maxLength,
                      scalarResolution, lengthResolution)
                  : !table->Build(property, component, range, maxLength))
    {
      vtkErrorWithObjectMacro(
        mapper, "The pre-integrated transfer-function table could not be built.");
      return false;
    }
    *rebuilt = true;
    mapper->UpdateProgress(1.0);
  }
  // Cell scalars: the functions at each cell value, for the cells' segments
  // (vtkHAVSCellOptics); rebuilt with the values or the functions.
  vtkHAVSCellOptics* optics = table->GetCellOptics();
  if (mesh->HasCellScalars())
  {
    if (optics->NeedsRebuild(property, component, mesh->GetScalarTime()))
    {
      if (!optics->Build(property, component, mesh->GetCellValues(), range, mesh->GetScalarTime()))
      {
        vtkErrorWithObjectMacro(mapper, "The cells' transfer-function values could not be built.");
        return false;
      }
      *rebuilt = true;
    }
  }
  else if (optics->GetNumberOfValues() > 0)
  {
    optics->Clear();
    *rebuilt = true;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSMapperInputs::WarnOnceBy(vtkObject* mapper, bool& warned, const std::string& message)
{
  if (!warned)
  {
    warned = true;
    vtkWarningWithObjectMacro(mapper, << message);
  }
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperInputs::CopyResult(
  const std::vector<float>* result, const int size[2], vtkFloatArray* rgba)
{
  if (!rgba || !result || result->empty())
  {
    return false;
  }
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(size[0]) * size[1]);
  std::copy(result->begin(), result->end(), rgba->GetPointer(0));
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSMapperInputs::RendererHasOpaqueGeometry(vtkRenderer* renderer)
{
  if (renderer->GetPreserveDepthBuffer())
  {
    return true;
  }
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && !vtkVolume::SafeDownCast(prop) && prop->HasOpaqueGeometry())
    {
      return true;
    }
  }
  return false;
}

VTK_ABI_NAMESPACE_END
