/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestMessages.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestMessages.h
 * @brief The error and warning events a VTK object sends, counted for the tests.
 */
#ifndef havsTestMessages_h
#define havsTestMessages_h

#include <string>

class vtkObject;

namespace havstest
{
/// Counts the error and warning events an object sends (and what they said).
struct Messages
{
  int Errors = 0;
  int Warnings = 0;
  std::string Text;
};
/// Starts counting on `object`; the returned pointer stays valid while the
/// object lives.
Messages* CountMessages(vtkObject* object);
}

#endif
