#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# gpu_check.sh: the GPU check in two steps (issue 47).
#
#   Apps/GPUBench/gpu_check.sh make [BUILD_DIR]   here: .gpubundle/havs-gpu-bundle.tar.xz
#                                                 (the blunt fin, the LOX post and gen1M at
#                                                 512² and 1024², every mapper; HAVS also
#                                                 with Table 4.3's settings: *_t43;
#                                                 the blunt fin's table at 64³, 128³
#                                                 and 256³ built by the compute shader)
#   Apps/GPUBench/gpu_check.sh run [OUT_DIR]      there, in the repository's root: the
#                                                 bundle's check, results under OUT_DIR
#                                                 (default $OUT, else gpu-check-out)
#
# With the device tool: make here, then
#   run(command="bash Apps/GPUBench/gpu_check.sh run", carry=[".gpubundle"], timeout_s=330)
# The run keeps to 270 s of checks (run_gpu_bundle.sh --budget), writing
# gpu-check.log and gpu-check.csv as it goes, so that a second try fits in
# 15 minutes of device time.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
case ${1:-} in
  make)
    build=${2:-$root/build}
    HAVS_DATA_DIR=${HAVS_DATA_DIR:-$root/../shared/data} \
      bash "$root/Apps/GPUBench/make_gpu_bundle.sh" "$build" "$root/.gpubundle" \
      --datasets bluntfin,loxpost,gen1M --sizes 512,1024 --cache-dir "$build/benchmark-cache" \
      --kinds havs_k2,havs_k6,havs_k2_t43,havs_k6_t43,cellprojection,raycast \
      --tables table64,table128,table256
    ;;
  run)
    out=${2:-${OUT:-gpu-check-out}}
    bash "$root/Apps/GPUBench/run_gpu_bundle.sh" "$root/.gpubundle/havs-gpu-bundle.tar.xz" "$out" \
      --budget 270
    ;;
  *)
    sed -n '3,19p' "$0"
    exit 2
    ;;
esac
