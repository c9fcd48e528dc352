/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRankCompositePass.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRankCompositePass.h"

#include "vtkCommunicator.h"
#include "vtkFloatArray.h"
#include "vtkHAVSMapperBase.h"
#include "vtkIceTCompositePass.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOrderedCompositingHelper.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSynchronizedRenderers.h"
#include "vtkTimeStamp.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

VTK_ABI_NAMESPACE_BEGIN
vtkStandardNewMacro(vtkHAVSRankCompositePass);

namespace
{
/// Why a frame keeps IceT's 8-bit image (the reduce takes the largest code
/// of all ranks: the first that applies on any rank).
enum Reason
{
  Eligible = 0,
  NotOrdered,   // IceT composites by depth (no volume asks for an order)
  Tiles,        // a tile display or an image reduction factor
  Selection,    // a selection render
  OtherProps,   // something besides one HAVS volume is visible on a rank
  NotKept,      // the mapper does not keep its float result (interaction, setting off)
  StaleResult,  // the mapper drew but kept no float result this frame
  SizeMismatch, // the result's size is not the window's
  WindowSizes,  // the ranks' windows differ
  NoTile,       // the displaying rank has no tile
  ReasonCount
};

const char* ReasonText(int reason)
{
  static const char* const texts[ReasonCount] = { "",
    "IceT composites by depth (no ordered compositing)", "a tile display or image reduction",
    "a selection render", "other props than one HAVS volume are visible",
    "the mapper keeps no float result (interaction, or the setting off)",
    "the mapper kept no float result this frame", "the float result is not the window's size",
    "the ranks' windows differ in size", "the displaying rank has no IceT tile" };
  return reason >= 0 && reason < ReasonCount ? texts[reason] : "unknown";
}

/**
 * The premultiplied RGBA images `images` (each `pixels` tuples of 4 floats)
 * put together front to back with "over" in the order `order` (indices into
 * `images`), in double, into `result` rounded to 8 bits (as OpenGL stores a
 * normalized colour).
 */
void CompositeFrontToBack(const std::vector<const float*>& images, const std::vector<int>& order,
  size_t pixels, unsigned char* result)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(pixels),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType p = first; p < last; ++p)
      {
        double sum[4] = { 0.0, 0.0, 0.0, 0.0 };
        for (int index : order)
        {
          const float* pixel = images[index] + 4 * p;
          const double behind = 1.0 - sum[3];
          for (int c = 0; c < 4; ++c)
          {
            sum[c] += behind * pixel[c];
          }
        }
        for (int c = 0; c < 4; ++c)
        {
          const double v = std::min(1.0, std::max(0.0, sum[c]));
          result[4 * p + c] = static_cast<unsigned char>(std::lround(v * 255.0));
        }
      }
    });
}
}

//------------------------------------------------------------------------------
vtkHAVSRankCompositePass::vtkHAVSRankCompositePass() = default;
vtkHAVSRankCompositePass::~vtkHAVSRankCompositePass() = default;

//------------------------------------------------------------------------------
void vtkHAVSRankCompositePass::SetIceTPass(vtkIceTCompositePass* pass)
{
  if (this->IceTPass != pass)
  {
    this->IceTPass = pass;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRankCompositePass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->IceTPass)
  {
    this->IceTPass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRankCompositePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->IceTPass)
  {
    return;
  }
  vtkTimeStamp before;
  before.Modified();
  this->IceTPass->Render(s);
  this->NumberOfRenderedProps = this->IceTPass->GetNumberOfRenderedProps();
  this->Composite(s, before.GetMTime());
}

//------------------------------------------------------------------------------
int vtkHAVSRankCompositePass::RankImage(
  const vtkRenderState* s, unsigned long since, const int size[2], vtkFloatArray* image) const
{
  vtkIceTCompositePass* icet = this->IceTPass;
  if (!icet->GetUseOrderedCompositing() || !icet->GetOrderedCompositingHelper())
  {
    return NotOrdered;
  }
  if (icet->GetTileDimensions()[0] != 1 || icet->GetTileDimensions()[1] != 1 ||
    icet->GetImageReductionFactor() != 1)
  {
    return Tiles;
  }
  vtkRenderer* renderer = s->GetRenderer();
  if (renderer->GetSelector())
  {
    return Selection;
  }
  // One visible volume whose mapper is a vtkHAVS mapper, or (an empty piece)
  // none with a mapper; nothing else.
  vtkHAVSMapperBase* mapper = nullptr;
  int volumes = 0;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    // Props without bounds draw nothing (ParaView keeps such actors, e.g. a
    // representation's empty selection or surface).
    const double* bounds = prop->GetBounds();
    if (!bounds || !vtkMath::AreBoundsInitialized(bounds))
    {
      continue;
    }
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (!volume)
    {
      return OtherProps;
    }
    if (!volume->GetMapper())
    {
      continue; // an empty piece: the representation draws nothing
    }
    mapper = vtkHAVSMapperBase::SafeDownCast(volume->GetMapper());
    if (!mapper || ++volumes > 1)
    {
      return OtherProps;
    }
  }
  if (mapper && !mapper->GetKeepFloatResult())
  {
    return NotKept;
  }
  const vtkIdType pixels = static_cast<vtkIdType>(size[0]) * size[1];
  if (mapper && mapper->GetFloatResultTime() > since)
  {
    // This frame's float result, copied once, into the array the gather sends.
    int keptSize[2] = { 0, 0 };
    if (!mapper->GetFloatResult(image, keptSize))
    {
      return StaleResult;
    }
    const bool fits = keptSize[0] == size[0] && keptSize[1] == size[1] &&
      image->GetNumberOfComponents() == 4 && image->GetNumberOfTuples() == pixels;
    return fits ? Eligible : SizeMismatch;
  }
  // No volume on this rank (an empty piece), or one not drawn this frame
  // (IceT did not ask this rank to draw, or its piece is outside the view):
  // transparent, as its image in IceT's composite.
  image->SetNumberOfComponents(4);
  image->SetNumberOfTuples(pixels);
  image->Fill(0.0);
  return Eligible;
}

//------------------------------------------------------------------------------
void vtkHAVSRankCompositePass::Composite(const vtkRenderState* s, unsigned long since)
{
  this->LastIceTDifference = -1;
  this->LastCompositeSeconds = 0.0;
  vtkMultiProcessController* controller = this->IceTPass->GetController();
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  if (ranks < 2)
  {
    this->LastFloatComposite = 0;
    this->LastReason = "one rank";
    return;
  }
  const double start = vtkTimerLog::GetUniversalTime();
  vtkRenderer* renderer = s->GetRenderer();
  const int* window = renderer->GetRenderWindow()->GetActualSize();
  const int size[2] = { window[0], window[1] };
  vtkNew<vtkFloatArray> image;
  // Every rank's verdict and window size, in one reduce: {reason, w, h, -w, -h}.
  const int mine[5] = { this->RankImage(s, since, size, image), size[0], size[1], -size[0],
    -size[1] };
  int all[5] = { 0, 0, 0, 0, 0 };
  controller->AllReduce(mine, all, 5, vtkCommunicator::MAX_OP);
  int reason = all[0];
  if (reason == Eligible && (all[1] != -all[3] || all[2] != -all[4]))
  {
    reason = WindowSizes;
  }
  if (reason != Eligible)
  {
    this->LastFloatComposite = 0;
    this->LastReason = ReasonText(reason);
    return;
  }
  const int rank = controller->GetLocalProcessId();
  const size_t pixels = static_cast<size_t>(size[0]) * size[1];
  std::vector<float> gathered(rank == 0 ? ranks * 4 * pixels : 0);
  controller->Gather(image->GetPointer(0), gathered.data(), static_cast<vtkIdType>(4 * pixels), 0);
  this->LastFloatComposite = 1;
  this->LastReason.clear();
  if (rank != 0)
  {
    this->LastCompositeSeconds = vtkTimerLog::GetUniversalTime() - start;
    return;
  }
  // ParaView displays IceT's single tile on rank 0.
  vtkSynchronizedRenderers::vtkRawImage tile; // shares IceT's pixels
  this->IceTPass->GetLastRenderedTile(tile);
  if (!tile.IsValid() || tile.GetWidth() != size[0] || tile.GetHeight() != size[1] ||
    tile.GetRawPtr()->GetNumberOfComponents() != 4)
  {
    this->LastFloatComposite = 0;
    this->LastReason = ReasonText(NoTile);
    return;
  }
  std::vector<const float*> images(ranks);
  for (int r = 0; r < ranks; ++r)
  {
    images[r] = gathered.data() + r * 4 * pixels;
  }
  // Front to back: the order ParaView gives IceT (icetCompositeOrder's first
  // image is the front one).
  const std::vector<int> order =
    this->IceTPass->GetOrderedCompositingHelper()->ComputeSortOrder(renderer->GetActiveCamera());
  std::vector<unsigned char> exact(4 * pixels);
  CompositeFrontToBack(images, order, pixels, exact.data());
  unsigned char* icet = tile.GetRawPtr()->GetPointer(0);
  int difference = 0;
  for (size_t i = 0; i < exact.size(); ++i)
  {
    difference = std::max(difference, std::abs(int(exact[i]) - int(icet[i])));
  }
  this->LastIceTDifference = difference;
  if (difference > this->MaximumIceTDifference)
  {
    this->LastFloatComposite = 0;
    this->LastReason = "the float composite differs from IceT's by more than its arithmetic "
                       "explains";
    if (!this->WarnedDifference)
    {
      this->WarnedDifference = true;
      vtkWarningMacro("The ranks' float composite differs from IceT's 8-bit composite by "
        << difference << "/255 (more than " << this->MaximumIceTDifference
        << "/255, what IceT's rounding explains); IceT's image is kept.");
    }
    return;
  }
  std::copy(exact.begin(), exact.end(), icet);
  if (this->IceTPass->GetDisplayRGBAResults())
  {
    tile.PushToViewport(renderer);
  }
  this->LastCompositeSeconds = vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
void vtkHAVSRankCompositePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IceTPass: " << this->IceTPass.GetPointer() << "\n";
  os << indent << "LastFloatComposite: " << this->LastFloatComposite << "\n";
  os << indent << "LastReason: " << this->LastReason << "\n";
  os << indent << "LastCompositeSeconds: " << this->LastCompositeSeconds << "\n";
  os << indent << "LastIceTDifference: " << this->LastIceTDifference << "\n";
  os << indent << "MaximumIceTDifference: " << this->MaximumIceTDifference << "\n";
}

VTK_ABI_NAMESPACE_END
