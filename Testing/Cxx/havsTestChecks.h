/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestChecks.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestChecks.h
 * @brief Counting checks of the vtkHAVS ctest programs (not part of the modules).
 *
 * A test calls Check()/CheckNear() for each assertion and returns Result():
 * EXIT_FAILURE when any failed. A test whose feature is absent here returns
 * SkipReturnCode (VTK's VTK_SKIP_RETURN_CODE, registered as ctest's
 * SKIP_RETURN_CODE), so that it shows as skipped, never as passed.
 */
#ifndef havsTestChecks_h
#define havsTestChecks_h

#include <string>

namespace havstest
{
/// VTK's VTK_SKIP_RETURN_CODE: ctest reports the test as skipped.
constexpr int SkipReturnCode = 125;

/// Counts failed checks.
int& Failures();
/// Prints and counts a failed check (and, with HAVS_TEST_VERBOSE set, prints a passed one).
bool Check(bool condition, const std::string& what);
/// |a - b| <= tol (and both finite), printed on failure.
bool CheckNear(double a, double b, double tol, const std::string& what);
/// EXIT_SUCCESS when no check failed, else EXIT_FAILURE.
int Result();
/// A size field of /proc/self/status in bytes ("VmRSS", "VmHWM"); -1 if absent.
long long ProcessStatusBytes(const char* field);
}

#endif
