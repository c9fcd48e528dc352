#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# The stand-alone GPU program (issue 16) on this machine's GPU (llvmpipe here):
#   - havs_benchmark --dump-case writes the frame cases (LOX post .vtk, blunt fin; 128²);
#   - havs_gpu_bench, with no VTK, draws each through every path the GPU has
#     (here framebuffer fetch and the interlock layout without a guard) and must
#     give the mapper's image;
#   - havs_gpu_bench needs no VTK library;
#   - the control: the faces drawn back to front must NOT give the mapper's image.
# Usage: TestHAVSGPUBench.sh <havs_benchmark> <havs_gpu_bench> <work dir>
set -u
benchmark=$1 bench=$2 work=$3
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
rm -rf "$work" && mkdir -p "$work"

if "$benchmark" --dump-case "$work" --datasets loxpostvtk,bluntfin --size 128; then
  ok "frame cases written"
else
  fail "havs_benchmark --dump-case"
fi
if ldd "$bench" | grep -q -i vtk; then
  fail "havs_gpu_bench links VTK: $(ldd "$bench" | grep -i vtk | head -3)"
else
  ok "havs_gpu_bench needs no VTK library (ldd: $(ldd "$bench" | awk '{print $1}' | tr '\n' ' '))"
fi
for d in loxpostvtk_128 bluntfin_128; do
  out="$work/$d.log"
  if "$bench" "$work/$d" --frames 3 > "$out" 2>&1; then
    ok "$d: every path drew the mapper's image"
  else
    fail "$d: havs_gpu_bench"
  fi
  cat "$out"
  for path in "framebuffer fetch" "interlock"; do
    grep -q "^| $path" "$out" && ok "$d: $path ran" || fail "$d: $path did not run"
  done
  if "$bench" "$work/$d" --frames 1 --reverse-order > "$out.control" 2>&1; then
    cat "$out.control"
    fail "$d: control: the faces back to front gave the mapper's image"
  else
    grep "^| " "$out.control"
    ok "$d: control: back to front the images differ"
  fi
done
if [ $failures -gt 0 ]; then
  echo "TestHAVSGPUBench: $failures FAILED"
  exit 1
fi
echo "TestHAVSGPUBench: PASSED"
