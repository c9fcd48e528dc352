/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSMapperGraphics.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSMapperGraphics
 * @brief   What vtkHAVSMapperBase asks of a mapper's graphics layer.
 *
 * The GL-free base cannot name OpenGL objects; its graphics layer
 * (vtkHAVSGLMapperResources, one per GL mapper) implements this interface,
 * and the GL mapper hands it to the base (vtkHAVSMapperBase::SetGraphics).
 * The base then releases the graphics resources and reads the kept float
 * result the same way for every mapper.
 */
#ifndef vtkHAVSMapperGraphics_h
#define vtkHAVSMapperGraphics_h

#include "vtkHAVSABINamespace.h"        // For VTK_ABI_NAMESPACE_BEGIN
#include "vtkHAVSCoreModule.h"          // For export macro
#include "vtkHAVSPreIntegrationTable.h" // For vtkHAVSPreIntegrationTable::Quadrature
#include "vtkObject.h"

#include <cstddef> // For size_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkRenderer;
class vtkWindow;

class VTKHAVSCORE_EXPORT vtkHAVSMapperGraphics : public vtkObject
{
public:
  vtkTypeMacro(vtkHAVSMapperGraphics, vtkObject);

  /// Releases everything in `window` (nullptr: in whichever window holds it).
  virtual void Release(vtkWindow* window) = 0;
  /// The last frame's kept float result and its size; nullptr without one.
  virtual const std::vector<float>* GetKeptResult(int size[2]) = 0;
  /// When the kept result was last made (a vtkTimeStamp's time; 0: never).
  virtual vtkMTimeType GetKeptResultTime() = 0;
  /// The bytes of the GPU buffers the graphics layer holds (on llvmpipe in
  /// host memory too): the memory ledger's "GPU buffers" (vtkHAVSMemory).
  virtual size_t GetMemoryBytes() const { return 0; }

  ///@{
  /**
   * Translucent geometry intermixed with the volume (vtkHAVSIntermixPass).
   * BeginIntermix: how many translucent layers `renderer` peeled this frame
   * and leaves to this volume, now taken (0: none, or another volume took
   * them; the kept float result is then the intermixed image). The base
   * then draws the view once per slab, SetIntermixSlab(i) before each
   * (i < layers: the volume up to layer i's depth; i == layers: up to the
   * opaque geometry), and EndIntermix(drawn) after (not drawn: the layers are
   * given back, and the pass composites them itself).
   */
  virtual int BeginIntermix(vtkRenderer* vtkNotUsed(renderer)) { return 0; }
  virtual void SetIntermixSlab(int vtkNotUsed(slab)) {}
  virtual void EndIntermix(bool vtkNotUsed(drawn)) {}
  ///@}

  /**
   * The pre-integrated table's entries built on the GPU
   * (vtkHAVSMapperBase::PreIntegrationOnGPU, vtkHAVSPreIntegrationTable::
   * EntryBuilder) in `renderer`'s window, for `mapper` (`mapperName` in its
   * errors); false where it cannot (the CPU builds them).
   */
  virtual bool BuildTableEntries(vtkRenderer* vtkNotUsed(renderer), vtkObject* vtkNotUsed(mapper),
    const char* vtkNotUsed(mapperName),
    const vtkHAVSPreIntegrationTable::Quadrature& vtkNotUsed(inputs), float* vtkNotUsed(table))
  {
    return false;
  }

protected:
  vtkHAVSMapperGraphics() = default;
  ~vtkHAVSMapperGraphics() override = default;

private:
  vtkHAVSMapperGraphics(const vtkHAVSMapperGraphics&) = delete;
  void operator=(const vtkHAVSMapperGraphics&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif
