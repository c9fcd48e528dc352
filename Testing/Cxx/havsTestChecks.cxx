/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestChecks.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "havsTestChecks.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace havstest
{
int& Failures()
{
  static int failures = 0;
  return failures;
}

bool Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    ++Failures();
    std::cerr << "CHECK FAILED: " << what << std::endl;
  }
  else if (std::getenv("HAVS_TEST_VERBOSE"))
  {
    std::cout << "ok: " << what << std::endl;
  }
  return condition;
}

bool CheckNear(double a, double b, double tol, const std::string& what)
{
  const bool ok = std::isfinite(a) && std::isfinite(b) && std::fabs(a - b) <= tol;
  if (!ok)
  {
    ++Failures();
    std::cerr << "CHECK FAILED: " << what << ": " << a << " vs " << b << " (tol " << tol << ")"
              << std::endl;
  }
  return ok;
}

int Result()
{
  return Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}

long long ProcessStatusBytes(const char* field)
{
  std::ifstream status("/proc/self/status");
  const std::string key = std::string(field) + ":";
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      return 1024LL * std::atoll(line.c_str() + key.size());
    }
  }
  return -1;
}
}
