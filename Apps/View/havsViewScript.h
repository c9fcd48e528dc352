/*=========================================================================

  Project:   vtkHAVS
  Module:    havsViewScript.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   havsview::Script
 * @brief   Scripted input for havs_view (--play FILE): a person's session,
 *          replayed through the same input functions.
 *
 * One command a line, `#` starts a comment. Positions are window pixels, y
 * down; buttons are left, middle, right.
 * - `drag BUTTON X0 Y0 X1 Y1 [STEPS]`: press, STEPS moves (default 10), release;
 * - `click BUTTON X Y`;
 * - `key C`: a key (one character, or `escape`);
 * - `tf-drag NODE T A`: drag opacity node NODE to t = T across the scalar
 *   range (0 … 1) and opacity A, with the mouse on the editor;
 * - `tf-add T A`, `tf-remove NODE`: a left click on the editor at (T, A), a
 *   right click on node NODE;
 * - `resize W H`;
 * - `screenshot PATH`: the image without the overlay, and PATH.txt, the state;
 * - `capture PATH`: the window as shown (status line and editor included);
 * - `quit`.
 */
#ifndef havsViewScript_h
#define havsViewScript_h

#include <string>
#include <vector>

namespace havsview
{
class Input;
class Scene;

class Script
{
public:
  /// Reads the commands of `path`; false with `error` when unreadable or wrong.
  bool Load(const std::string& path, std::string& error);

  /// Runs the next command; false when there is none left (or one failed).
  bool Step(Input& input, Scene& scene);

  /// Whether a command failed (its message in GetError()).
  bool GetFailed() const { return !this->Error.empty(); }
  const std::string& GetError() const { return this->Error; }

private:
  std::vector<std::vector<std::string>> Commands;
  std::vector<int> Lines;
  size_t Next = 0;
  std::string Error;
};
}

#endif
