#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# The GL-free core has no OpenGL or EGL dependency: neither the libraries of
# vtkHAVS::Core and vtkHAVS::Validation (their NEEDED entries) nor the core
# test driver, a program built from the core alone that runs the core tests
# (everything it loads, ldd). The control: the same check on the OpenGL
# module's library must find GL, or the check proves nothing.
# Arguments: CORE_LIBRARY VALIDATION_LIBRARY CORE_DRIVER OPENGL_LIBRARY
set -u
core=$1 validation=$2 driver=$3 opengl=$4
gl='lib(GL|GLX|EGL|OpenGL|GLEW|glapi|OSMesa)\.so|libvtkRenderingOpenGL2|libvtkHAVSOpenGL|libvtkHAVSHeadless'
failures=0
needed() { readelf -d "$1" | awk '/NEEDED/ {gsub(/[\[\]]/, "", $5); print $5}'; }
for lib in "$core" "$validation"; do
  if needed "$lib" | grep -qE "$gl"; then
    echo "FAIL: $(basename "$lib") needs $(needed "$lib" | grep -E "$gl" | tr '\n' ' ')"
    failures=$((failures + 1))
  else
    echo "ok   $(basename "$lib") needs no GL library: $(needed "$lib" | tr '\n' ' ')"
  fi
done
if ldd "$driver" | grep -qE "$gl"; then
  echo "FAIL: the core test driver loads $(ldd "$driver" | grep -oE "[^ ]*($gl)[^ ]*" | sort -u | tr '\n' ' ')"
  failures=$((failures + 1))
else
  echo "ok   the core test driver ($(basename "$driver"), $(ldd "$driver" | wc -l) libraries) loads no GL library"
fi
if "$driver" TestHAVSRadixSorter > /dev/null 2>&1; then
  echo "ok   the core-only program runs (TestHAVSRadixSorter)"
else
  echo "FAIL: the core-only program does not run"
  failures=$((failures + 1))
fi
# The control.
if needed "$opengl" | grep -qE "$gl"; then
  echo "ok   control: $(basename "$opengl") needs $(needed "$opengl" | grep -E "$gl" | tr '\n' ' ')"
else
  echo "FAIL: control: the check does not see GL in $(basename "$opengl")"
  failures=$((failures + 1))
fi
[ $failures -eq 0 ] && echo "TestHAVSCoreHasNoGL: PASSED" || echo "TestHAVSCoreHasNoGL: $failures FAILED"
exit $((failures > 0))
