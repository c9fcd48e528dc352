// (in progress: replaced by the RayCast part)
#include "havsGPUBench.h"

namespace havsgpu
{
bool MakeRayCastPaths(Case&, const Options&, const Device&, Paths& paths)
{
  paths.NotRun.push_back("the RayCast part is not written yet");
  return true;
}
}
