#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# The stand-alone GPU program (issues 16, 47) on this machine's GPU (llvmpipe here):
#   - havs_benchmark --dump-case writes the frame cases of every mapper (HAVS at
#     k = 2 and 6, the cell projection, the ray caster; LOX post .vtk and the
#     blunt fin at 128²) with the exact reference's image;
#   - havs_gpu_cases, the GL-free case builder, makes the same arrays and table
#     from the core mappers, byte for byte (control: a changed byte is found);
#   - havs_gpu_bench, with no VTK, draws each case through every path the GPU
#     has (here framebuffer fetch, the interlock layout without a guard,
#     fragment lists; the cell projection; the ray caster's peel and cast) and
#     must give the mapper's image and the exact image;
#   - havs_gpu_bench needs no VTK library, havs_gpu_cases no OpenGL;
#   - the control: each case's wrong order must NOT give the exact image.
# Usage: TestHAVSGPUBench.sh <havs_benchmark> <havs_gpu_bench> <havs_gpu_cases> <work dir>
set -u
benchmark=$1 bench=$2 builder=$3 work=$4
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
rm -rf "$work" && mkdir -p "$work"

if "$benchmark" --dump-case "$work" --datasets loxpostvtk,bluntfin --size 128 \
  --cache-dir "$work/cache"; then
  ok "frame cases written"
else
  fail "havs_benchmark --dump-case"
fi
if ldd "$bench" | grep -q -i vtk; then
  fail "havs_gpu_bench links VTK: $(ldd "$bench" | grep -i vtk | head -3)"
else
  ok "havs_gpu_bench needs no VTK library (ldd: $(ldd "$bench" | awk '{print $1}' | tr '\n' ' '))"
fi
if ldd "$builder" | grep -q -i -E 'libGL|libEGL|OpenGL|X11'; then
  fail "havs_gpu_cases links OpenGL: $(ldd "$builder" | grep -i -E 'GL|X11' | head -3)"
else
  ok "havs_gpu_cases needs no OpenGL library"
fi

cases=()
for d in loxpostvtk_128 bluntfin_128; do
  for kind in havs_k2 havs_k6 cellprojection raycast; do
    cases+=("$work/${d}_$kind")
  done
done
# The builder against the GL capture, byte for byte.
if VTK_SMP_BACKEND_IN_USE=STDThread "$builder" "${cases[@]}" --check > "$work/check.log" 2>&1; then
  ok "havs_gpu_cases made the captured arrays and tables byte for byte"
else
  fail "havs_gpu_cases --check"
fi
grep -v "the same" "$work/check.log"
# Control: one changed byte of one array must be found.
cp -r "$work/bluntfin_128_cellprojection" "$work/control_case"
printf '\x01' | dd of="$work/control_case/order.u32" bs=1 seek=5 conv=notrunc status=none
if VTK_SMP_BACKEND_IN_USE=STDThread "$builder" "$work/control_case" --check > /dev/null 2>&1; then
  fail "control: a changed byte of order.u32 was not found"
else
  ok "control: a changed byte of order.u32 is found"
fi
rm -rf "$work/control_case"

for c in "${cases[@]}"; do
  name=$(basename "$c")
  out="$work/$name.log"
  if "$bench" "$c" --frames 2 > "$out" 2>&1; then
    ok "$name: every path drew the mapper's and the exact image"
  else
    fail "$name: havs_gpu_bench"
  fi
  grep -E "^\| |^## |^not run" "$out" | grep -v "^|---"
  case $name in
    *havs_k*) paths=("framebuffer fetch" "interlock" "fragment lists" "raster bound") ;;
    *cellprojection) paths=("cell projection" "raster bound") ;;
    *raycast) paths=("ray caster" "raster bound") ;;
  esac
  for path in "${paths[@]}"; do
    grep -q "^| $path" "$out" && ok "$name: $path ran" || fail "$name: $path did not run"
  done
  "$bench" "$c" --frames 1 --control > "$out.control" 2>&1
  grep "^| " "$out.control" | grep -v "^|---"
  # Every path with an image must miss the bound (no row says "exact").
  if grep -q "FAILED (exact bound)" "$out.control" && ! grep -q "| exact |" "$out.control"; then
    ok "$name: control: the wrong order misses the exact image on every path"
  else
    fail "$name: control: a path drew the exact image from the wrong order"
  fi
done
if [ $failures -gt 0 ]; then
  echo "TestHAVSGPUBench: $failures FAILED"
  exit 1
fi
echo "TestHAVSGPUBench: PASSED"
