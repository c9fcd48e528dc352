// (in progress: replaced by the CellProjection part)
#include "havsGPUBench.h"

namespace havsgpu
{
bool MakeCellProjectionPaths(Case&, const Options&, const Device&, Paths& paths)
{
  paths.NotRun.push_back("the CellProjection part is not written yet");
  return true;
}
}
