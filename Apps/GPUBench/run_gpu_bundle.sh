#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# run_gpu_bundle.sh: the GPU check (issue 47) on the machine it runs on.
#
#   run_gpu_bundle.sh BUNDLE.tar.xz OUT_DIR [--frames N] [--budget SECONDS] [--no-control]
#
# Unpacks the bundle of make_gpu_bundle.sh, says which EGL device and driver
# it found, then, case by case from the smallest frame to the largest:
# havs_gpu_cases makes the case's arrays (faces, orders, records) from its
# mesh, havs_gpu_bench draws it through every path the GPU has and compares
# it with the exact image. Everything goes to OUT_DIR as it comes
# (gpu-check.log, gpu-check.csv), so that a run cut short still leaves what
# it did; cases left when --budget (default 270 s) is spent are listed as not
# run. The control (on the smallest cases): the wrong orders, which must
# miss the exact image. Table cases (make_gpu_bundle.sh --tables): the
# pre-integrated table built by the compute shader against the CPU's, timed
# on both; the control, the functions mirrored, must miss. Exit status 0 only when every case that ran drew the
# exact image on every path, every control missed it, and nothing was left.
set -u -o pipefail
if [ $# -lt 2 ]; then
  sed -n '3,16p' "$0"
  exit 2
fi
bundle=$1
out=$2
shift 2
frames=5
budget=270
control=1
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    --no-control) control=0; shift ;;
    *) echo "run_gpu_bundle.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
log="$out/gpu-check.log"
csv="$out/gpu-check.csv"
rm -f "$log" "$csv"
say() { echo "$@" | tee -a "$log"; }
start=$(date +%s)
left() { echo $((budget - ($(date +%s) - start))); }

work=$(mktemp -d "${TMPDIR:-/tmp}/havs-gpu.XXXXXX")
trap 'rm -rf "$work"' EXIT
if ! tar -C "$work" -xJf "$bundle" 2> /dev/null &&
  ! python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' \
    "$bundle" "$work"; then # (an image without xz: Python's lzma)
  say "FAILED: cannot unpack $bundle (tar with xz, or python3)"
  exit 1
fi
b="$work/havs-gpu"
say "# vtkHAVS GPU check ($(date -u +%Y-%m-%dT%H:%MZ), $(uname -m), $(nproc) cores)"

# EGL: the image's libglvnd, else the carried one; the NVIDIA driver's own
# folder and vendor file where a container mounts them.
if ! ldconfig -p 2>/dev/null | grep -q 'libEGL.so.1 '; then
  export LD_LIBRARY_PATH="$b/lib/glvnd${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  say "libEGL.so.1: none in the image, the carried libglvnd is used"
fi
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
  if [ -d "$d" ]; then export LD_LIBRARY_PATH="${LD_LIBRARY_PATH:+$LD_LIBRARY_PATH:}$d"; fi
done
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then
  found=""
  for f in /usr/share/glvnd/egl_vendor.d/10_nvidia.json /etc/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$f" ]; then found=$f; fi
  done
  if [ -z "$found" ] && [ -f /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]; then
    export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
    say "__EGL_VENDOR_LIBRARY_FILENAMES=$__EGL_VENDOR_LIBRARY_FILENAMES (the driver's folder)"
  fi
fi
if command -v nvidia-smi > /dev/null; then
  nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>&1 |
    sed 's/^/nvidia-smi: /' | tee -a "$log"
fi
cases_env=(env "LD_LIBRARY_PATH=$b/lib/vtk${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  VTK_SMP_BACKEND_IN_USE=STDThread)
if ! "${cases_env[@]}" "$b/bin/havs_gpu_cases" --help > /dev/null 2>&1; then
  say "FAILED: havs_gpu_cases does not start here:"
  "${cases_env[@]}" ldd "$b/bin/havs_gpu_cases" 2>&1 | grep -i 'not found' | tee -a "$log"
  exit 1
fi

# The cases grouped by data set and size (one mesh, one frame size), the
# groups by frame size, then by mesh size: the small ones first.
declare -A members
for d in "$b"/cases/*/; do
  group=$(awk '$1 == "dataset" { s = $2 } $1 == "width" { w = $2 } END { print s "_" w }' \
    "$d/case.txt")
  members[$group]+="$d "
done
mapfile -t groups < <(
  for group in "${!members[@]}"; do
    first=${members[$group]%% *}
    cells=$(awk '$1 == "cells" { print $2 }' "$first/case.txt")
    echo "${group##*_} ${cells:-0} $group"
  done | sort -n -k1,1 -k2,2 | awk '{ print $3 }')
failures=0
notrun=()
declare -A controlled
for group in "${groups[@]}"; do
  read -r -a dirs <<< "${members[$group]}"
  if [ "$(left)" -le 10 ]; then
    notrun+=("$group (the time budget was spent)")
    continue
  fi
  say ""
  say "## $group ($(left) s left)"
  if ! timeout "$(left)" "${cases_env[@]}" "$b/bin/havs_gpu_cases" "${dirs[@]}" 2>&1 |
    tee -a "$log"; then
    say "FAILED: havs_gpu_cases $group"
    failures=$((failures + 1))
    continue
  fi
  if ! timeout "$(left)" "$b/bin/havs_gpu_bench" "${dirs[@]}" --frames "$frames" --csv "$csv" \
    2>&1 | tee -a "$log"; then
    say "FAILED (or cut short): havs_gpu_bench $group"
    failures=$((failures + 1))
  fi
  # The controls: the first group of frames and the first of tables.
  kind=frames
  if grep -q '^mapper table' "${dirs[0]}/case.txt"; then kind=tables; fi
  if [ -z "${controlled[$kind]:-}" ] && [ "$control" = 1 ] && [ "$(left)" -gt 10 ]; then
    controlled[$kind]=1
    # The control: each mapper's wrong order must miss the exact image (a
    # table: the functions mirrored must miss the CPU's table).
    for d in "${dirs[@]}"; do
      if timeout "$(left)" "$b/bin/havs_gpu_bench" "$d" --frames 1 --control --csv "$csv" \
        >> "$log" 2>&1; then
        say "FAILED: the control of $(basename "$d") drew the exact image"
        failures=$((failures + 1))
      else
        say "control $(basename "$d"): misses the exact image, as it must"
      fi
    done
  fi
  # The arrays are not needed any more: the disk holds one group's at a time.
  for d in "${dirs[@]}"; do
    find "$d" -name '*.f32' ! -name 'table.f32' -delete
    find "$d" \( -name '*.u32' -o -name '*.i32' \) -delete
  done
done
for n in "${notrun[@]}"; do
  say "not run: $n"
done
say ""
say "elapsed $(($(date +%s) - start)) s"
if [ $failures -gt 0 ] || [ ${#notrun[@]} -gt 0 ]; then
  say "run_gpu_bundle.sh: FAILED ($failures failures, ${#notrun[@]} groups not run)"
  exit 1
fi
say "run_gpu_bundle.sh: every path of every case drew the exact image"
