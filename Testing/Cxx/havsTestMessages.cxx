/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestMessages.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestMessages.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <map>
#include <memory>

namespace havstest
{
namespace
{
std::map<vtkObject*, std::unique_ptr<Messages>>& MessageStore()
{
  static std::map<vtkObject*, std::unique_ptr<Messages>> store;
  return store;
}

void OnMessage(vtkObject* caller, unsigned long event, void*, void* callData)
{
  Messages* m = MessageStore()[caller].get();
  if (event == vtkCommand::ErrorEvent)
  {
    ++m->Errors;
  }
  else
  {
    ++m->Warnings;
  }
  if (callData)
  {
    m->Text += static_cast<const char*>(callData);
    m->Text += "\n";
  }
}
}

Messages* CountMessages(vtkObject* object)
{
  auto& slot = MessageStore()[object];
  slot.reset(new Messages);
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnMessage);
  object->AddObserver(vtkCommand::ErrorEvent, callback);
  object->AddObserver(vtkCommand::WarningEvent, callback);
  return slot.get();
}

}
