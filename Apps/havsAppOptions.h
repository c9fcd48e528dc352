/*=========================================================================

  Project:   vtkHAVS
  Module:    havsAppOptions.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsAppOptions.h
 * @brief Command-line helpers shared by the vtkHAVS apps.
 */
#ifndef havsAppOptions_h
#define havsAppOptions_h

#include <sstream>
#include <string>
#include <vector>

namespace havsapp
{
/// "a,b,,c" -> { "a", "b", "c" }.
inline std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}
}

#endif
