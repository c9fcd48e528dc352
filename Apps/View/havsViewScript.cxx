/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewScript.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsViewScript.h"

#include "havsViewInput.h"
#include "havsViewScene.h"

#include "vtkRenderer.h"

#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace havsview
{
namespace
{
// Words each command takes (the command included); -1: at least that many.
const std::map<std::string, std::pair<size_t, size_t>> kArity = {
  { "drag", { 6, 7 } },
  { "click", { 4, 4 } },
  { "key", { 2, 2 } },
  { "tf-drag", { 4, 4 } },
  { "tf-add", { 3, 3 } },
  { "tf-remove", { 2, 2 } },
  { "resize", { 3, 3 } },
  { "screenshot", { 2, 2 } },
  { "capture", { 2, 2 } },
  { "quit", { 1, 1 } },
};

int Button(const std::string& name)
{
  if (name == "left")
  {
    return Input::Left;
  }
  if (name == "middle")
  {
    return Input::Middle;
  }
  if (name == "right")
  {
    return Input::Right;
  }
  return -1;
}
}

//------------------------------------------------------------------------------
bool Script::Load(const std::string& path, std::string& error)
{
  std::ifstream in(path);
  if (!in)
  {
    error = "cannot read the script " + path;
    return false;
  }
  std::string line;
  int number = 0;
  while (std::getline(in, line))
  {
    ++number;
    const size_t hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::istringstream words(line);
    std::vector<std::string> command;
    for (std::string word; words >> word;)
    {
      command.push_back(word);
    }
    if (command.empty())
    {
      continue;
    }
    auto arity = kArity.find(command[0]);
    if (arity == kArity.end() || command.size() < arity->second.first ||
      command.size() > arity->second.second)
    {
      error = path + ":" + std::to_string(number) + ": not a command: " + line;
      return false;
    }
    this->Commands.push_back(command);
    this->Lines.push_back(number);
  }
  return true;
}

//------------------------------------------------------------------------------
bool Script::Step(Input& input, Scene& scene)
{
  if (this->Next >= this->Commands.size() || this->GetFailed())
  {
    return false;
  }
  const std::vector<std::string>& c = this->Commands[this->Next];
  const int line = this->Lines[this->Next++];
  std::cout << "havs_view: script line " << line << ":";
  for (const auto& word : c)
  {
    std::cout << " " << word;
  }
  std::cout << std::endl;
  try
  {
    const std::string& what = c[0];
    const int height = scene.GetRenderer()->GetRenderWindow()->GetSize()[1];
    auto press = [&](int button, double x, double y, bool down)
    { input.MouseButton(button, down, x, y, false, false); };
    if (what == "drag")
    {
      const int button = Button(c[1]);
      const double x0 = std::stod(c[2]), y0 = std::stod(c[3]);
      const double x1 = std::stod(c[4]), y1 = std::stod(c[5]);
      const int steps = c.size() > 6 ? std::stoi(c[6]) : 10;
      if (button < 0 || steps < 1)
      {
        throw std::invalid_argument("button or steps");
      }
      input.CursorMove(x0, y0);
      press(button, x0, y0, true);
      for (int i = 1; i <= steps; ++i)
      {
        const double t = static_cast<double>(i) / steps;
        input.CursorMove(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
      }
      press(button, x1, y1, false);
    }
    else if (what == "click")
    {
      const int button = Button(c[1]);
      if (button < 0)
      {
        throw std::invalid_argument("button");
      }
      const double x = std::stod(c[2]), y = std::stod(c[3]);
      input.CursorMove(x, y);
      press(button, x, y, true);
      press(button, x, y, false);
    }
    else if (what == "key")
    {
      input.Key(c[1]);
    }
    else if (what == "tf-drag" || what == "tf-remove")
    {
      double x, y;
      if (!scene.GetEditor().GetNodePosition(std::stoi(c[1]), x, y))
      {
        this->Error = "line " + std::to_string(line) + ": no opacity node " + c[1];
        return false;
      }
      const double yDown = height - 1 - y;
      input.CursorMove(x, yDown);
      if (what == "tf-remove")
      {
        press(Input::Right, x, yDown, true);
        press(Input::Right, x, yDown, false);
      }
      else
      {
        double tx, ty;
        scene.GetEditor().GetPlotPosition(std::stod(c[2]), std::stod(c[3]), tx, ty);
        const double tyDown = height - 1 - ty;
        press(Input::Left, x, yDown, true);
        for (int i = 1; i <= 4; ++i)
        {
          const double t = i / 4.0;
          input.CursorMove(x + t * (tx - x), yDown + t * (tyDown - yDown));
        }
        press(Input::Left, tx, tyDown, false);
      }
    }
    else if (what == "tf-add")
    {
      double x, y;
      scene.GetEditor().GetPlotPosition(std::stod(c[1]), std::stod(c[2]), x, y);
      const double yDown = height - 1 - y;
      input.CursorMove(x, yDown);
      press(Input::Left, x, yDown, true);
      press(Input::Left, x, yDown, false);
    }
    else if (what == "resize")
    {
      input.Resize(std::stoi(c[1]), std::stoi(c[2]));
    }
    else if (what == "screenshot" || what == "capture")
    {
      if (!input.Screenshot(c[1], what == "capture"))
      {
        this->Error = "line " + std::to_string(line) + ": the screenshot failed";
        return false;
      }
    }
    else if (what == "quit")
    {
      input.Key("q");
    }
  }
  catch (const std::exception&)
  {
    this->Error = "line " + std::to_string(line) + ": bad arguments";
    return false;
  }
  return true;
}
}
