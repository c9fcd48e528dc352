/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSLevelOfDetailController.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSLevelOfDetailController with synthetic frame times: a frame at
// fraction f takes a + b f (the boundary's fixed part a, the internal faces'
// b f; a full frame 1.05 s), times a +-3 % noise from a fixed sequence.
// - a 0.2 s target from a full frame: within 10 % of the target in 15 frames,
//   the fraction only falling (no overshoot), and constant once there (the
//   noise stays inside the dead band);
// - a larger target: the fraction rises to the new level without overshoot;
// - a budget the full frame fits: full quality at once;
// - a target below the boundary's own time: the boundary only;
// Control: an over-eager gain (2) overshoots, and the same check catches it.
#include "havsTestChecks.h"

#include "vtkHAVSLevelOfDetailController.h"

#include "vtkNew.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Run
{
  std::vector<double> Fractions;
  std::vector<double> Seconds;
};

/// Frames at the controller's choices under `target`, from where it is.
Run Drive(vtkHAVSLevelOfDetailController* control, double a, double b, double target, int frames)
{
  Run run;
  unsigned int state = 12345u;
  for (int i = 0; i < frames; ++i)
  {
    const double f = control->Choose(target);
    state = state * 1103515245u + 12345u;
    const double noise = 1.0 + 0.03 * (((state >> 16) & 0x7fff) / 16383.5 - 1.0);
    const double t = (a + b * f) * noise;
    control->FrameDrawn(f, t);
    run.Fractions.push_back(f);
    run.Seconds.push_back(t);
  }
  return run;
}

/// The fraction never turns back: monotone over the run.
bool Monotone(const std::vector<double>& f)
{
  int direction = 0;
  for (size_t i = 1; i < f.size(); ++i)
  {
    const int d = f[i] > f[i - 1] ? 1 : (f[i] < f[i - 1] ? -1 : 0);
    if (d != 0 && direction != 0 && d != direction)
    {
      return false;
    }
    direction = d != 0 ? d : direction;
  }
  return true;
}

void Print(const char* name, const Run& run)
{
  std::printf("%s:", name);
  for (size_t i = 0; i < run.Fractions.size(); i += 3)
  {
    std::printf(" %.3f/%.0fms", run.Fractions[i], 1000.0 * run.Seconds[i]);
  }
  std::printf("\n");
}
}

int TestHAVSLevelOfDetailController(int, char*[])
{
  const double a = 0.05, b = 1.0;
  vtkNew<vtkHAVSLevelOfDetailController> control;
  control->FrameDrawn(1.0, a + b); // the still frame before the interaction

  Run toTarget = Drive(control, a, b, 0.2, 40);
  Print("target 200 ms", toTarget);
  havstest::Check(
    std::abs(toTarget.Seconds[15] - 0.2) < 0.02 && std::abs(toTarget.Seconds.back() - 0.2) < 0.02,
    "a 0.2 s target: within 10 % of it after 15 frames");
  havstest::Check(Monotone(toTarget.Fractions), "a 0.2 s target: no overshoot");
  bool steady = true;
  for (size_t i = 20; i < toTarget.Fractions.size(); ++i)
  {
    steady = steady && toTarget.Fractions[i] == toTarget.Fractions[19];
  }
  havstest::Check(steady, "a 0.2 s target: the noise does not move the fraction once there");

  Run larger = Drive(control, a, b, 0.5, 30);
  Print("target 500 ms", larger);
  havstest::Check(Monotone(larger.Fractions) &&
      larger.Fractions.back() > toTarget.Fractions.back() &&
      std::abs(larger.Seconds.back() - 0.5) < 0.05,
    "a larger target: the fraction rises to it without overshoot");

  havstest::Check(control->Choose(2.0) == 1.0, "a budget the full frame fits: full quality");
  Run still = Drive(control, a, b, 1e4, 3);
  havstest::Check(
    still.Fractions[0] == 1.0 && still.Fractions[2] == 1.0, "the still budget: full quality");

  Run tight = Drive(control, 0.3, b, 0.2, 40);
  Print("target below the boundary's time", tight);
  havstest::Check(tight.Fractions.back() == 0.0, "a target below the boundary: the boundary only");

  // Control: gain 2 overshoots (the step's derivative at the fixed point is
  // 1 - 2 (1 - a / target) < 0): the monotone check fails on it.
  vtkNew<vtkHAVSLevelOfDetailController> eager;
  eager->SetGain(2.0);
  eager->FrameDrawn(1.0, a + b);
  Run overshoot = Drive(eager, a, b, 0.2, 40);
  Print("control, gain 2", overshoot);
  havstest::Check(!Monotone(overshoot.Fractions), "control: gain 2 overshoots and is caught");
  return havstest::Result();
}
