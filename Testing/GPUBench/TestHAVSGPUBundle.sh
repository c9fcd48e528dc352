#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# The GPU check's bundle (issue 47), made and run here on llvmpipe as it runs
# on a GPU machine: make_gpu_bundle.sh (LOX post .vtk, the blunt fin and a
# generated block at 128², every mapper; the LOX post's table at 16³ and 33³
# built by the compute shader), then run_gpu_bundle.sh, which
# unpacks it, makes every case's arrays and table with the carried
# havs_gpu_cases and its carried VTK libraries, draws every path with
# havs_gpu_bench against the exact image, and runs the controls.
# Checks: the bundle and its size table are written and under the limit; the
# run passes; it said which EGL device it ran on; the controls missed; every
# case of every mapper appears in the CSV with an exact verdict, each table
# case as equal to the CPU's table; control of
# the check: a bundle whose exact images are changed must fail the run.
# Usage: TestHAVSGPUBundle.sh <source dir> <build dir> <work dir>
set -u
src=$1 build=$2 work=$3
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
rm -rf "$work" && mkdir -p "$work"

if bash "$src/Apps/GPUBench/make_gpu_bundle.sh" "$build" "$work/bundle" \
  --datasets loxpostvtk,bluntfin,block24 --sizes 128 --tables table16,table33 \
  --cache-dir "$work/cache" > "$work/make.log" 2>&1; then
  ok "bundle made"
else
  fail "make_gpu_bundle.sh"
fi
tail -12 "$work/make.log"
[ -s "$work/bundle/bundle-size.txt" ] && ok "size table written" || fail "no bundle-size.txt"

bash "$src/Apps/GPUBench/run_gpu_bundle.sh" "$work/bundle/havs-gpu-bundle.tar.xz" "$work/out" \
  --frames 2 > "$work/run.log" 2>&1
rc=$?
grep -E "^## |^control|^FAIL|^not run|^elapsed|^run_gpu|^GPU:|^paths" "$work/run.log"
[ $rc -eq 0 ] && ok "run_gpu_bundle.sh passed" || fail "run_gpu_bundle.sh exited $rc"
grep -q "^GPU: .*EGL" "$work/out/gpu-check.log" && ok "the EGL device is said" ||
  fail "the log does not say which GPU and EGL"
controls=$(grep -c "misses the exact image, as it must" "$work/out/gpu-check.log")
[ "$controls" -eq 5 ] && ok "5 controls missed (4 frames, 1 table)" ||
  fail "$controls controls missed the exact image, 5 expected (4 frames, 1 table)"
for d in loxpostvtk_128 bluntfin_128 block24_128; do
  for kind in havs_k2 havs_k6 cellprojection raycast; do
    rows=$(grep -c "^${d}_$kind,.*,exact,0$" "$work/out/gpu-check.csv")
    [ "$rows" -ge 1 ] && ok "${d}_$kind: $rows exact paths" || fail "${d}_$kind: no exact path"
  done
done

# The check's own control: wrong exact images (every value halved) must fail it.
for t in table16 table33; do
  rows=$(grep -c "^loxpostvtk_128_$t,table,.*,equal,0$" "$work/out/gpu-check.csv")
  [ "$rows" -eq 1 ] && ok "loxpostvtk_128_$t: the GPU's table equals the CPU's" ||
    fail "loxpostvtk_128_$t: no equal table row"
done

mkdir -p "$work/bad" && tar -C "$work/bad" -xJf "$work/bundle/havs-gpu-bundle.tar.xz"
for f in "$work"/bad/havs-gpu/cases/*/reference.u16; do
  python3 -c "import sys,array; a=array.array('H'); a.frombytes(open(sys.argv[1],'rb').read()); a=array.array('H',(v//2 for v in a)); open(sys.argv[1],'wb').write(a.tobytes())" "$f"
done
tar -C "$work/bad" -cJf "$work/bad.tar.xz" havs-gpu
if bash "$src/Apps/GPUBench/run_gpu_bundle.sh" "$work/bad.tar.xz" "$work/out-bad" --frames 1 \
  --no-control > "$work/run-bad.log" 2>&1; then
  fail "control: a bundle with wrong exact images passed"
else
  ok "control: a bundle with wrong exact images fails ($(grep -c 'FAILED (exact bound)' "$work/out-bad/gpu-check.log") paths)"
fi
if [ $failures -gt 0 ]; then
  echo "TestHAVSGPUBundle: $failures FAILED"
  exit 1
fi
echo "TestHAVSGPUBundle: PASSED"
