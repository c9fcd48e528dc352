#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# make_gpu_bundle.sh: the GPU check's bundle (issue 47), made on this machine.
#
#   Apps/GPUBench/make_gpu_bundle.sh BUILD_DIR OUT_DIR [--datasets a,b] [--sizes 512,1024]
#                                    [--kinds a,b] [--tables a,b] [--cache-dir DIR]
#                                    [--limit-mib N]
#
# Writes OUT_DIR/havs-gpu-bundle.tar.xz (and OUT_DIR/bundle-size.txt, what it
# holds and how big each part is), for run_gpu_bundle.sh on a machine with a
# GPU and no VTK:
#   - the frame cases of view 0 of each data set at each size, for every
#     mapper (havs_k2, havs_k6, cellprojection, raycast), written by
#     `havs_benchmark --dump-case` with the exact reference's image
#     (reference.u16) and folded-pixel mask, WITHOUT their large arrays, their
#     pre-integration table and the mapper's llvmpipe result: the arrays and
#     the table are made again there (havs_gpu_cases);
#   - with --tables (e.g. table64,table128): table cases of the first data
#     set, once: its pre-integrated table built by the GPU's compute shader
#     against the CPU's build (issue 45), both made there;
#   - the real meshes (.havsmesh: points, tetrahedra, scalars; the generated
#     blocks gen1M, gen4M, gen10M and block<N> travel as their name only);
#   - havs_gpu_bench (no VTK, the C++ runtime linked in) and havs_gpu_cases
#     with the libraries it needs: vtkHAVS::Core and the VTK modules it links
#     (Debian's; no OpenGL, no I/O), which run on glibc >= 2.36;
#   - libglvnd's libEGL.so.1 and libGLdispatch.so.0, for an image without them;
#   - run_gpu_bundle.sh and README.md.
# Fails when the compressed bundle is larger than --limit-mib (default 56:
# the device tool carries at most 64 MiB with the project's tree).
set -euo pipefail

if [ $# -lt 2 ]; then
  sed -n '3,29p' "$0"
  exit 2
fi
build=$(cd "$1" && pwd)
out=$2
shift 2
datasets=bluntfin,loxpost,gen1M
sizes=512,1024
cache="$build/benchmark-cache"
kinds=havs_k2,havs_k6,cellprojection,raycast
tables=""
limit=56
while [ $# -gt 0 ]; do
  case $1 in
    --datasets) datasets=$2; shift 2 ;;
    --sizes) sizes=$2; shift 2 ;;
    --kinds) kinds=$2; shift 2 ;;
    --tables) tables=$2; shift 2 ;;
    --cache-dir) cache=$2; shift 2 ;;
    --limit-mib) limit=$2; shift 2 ;;
    *) echo "make_gpu_bundle.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
b="$stage/havs-gpu"
mkdir -p "$b/cases" "$b/bin" "$b/lib/vtk" "$b/lib/glvnd"

t0=$(date +%s)
for size in ${sizes//,/ }; do
  "$build/bin/havs_benchmark" --dump-case "$b/cases" --datasets "$datasets" --size "$size" \
    --cache-dir "$cache" --dump-kinds "$kinds"
done
# The large arrays and the table are made again where the bundle runs (havs_gpu_cases); the
# mapper's float result on llvmpipe stays here (the check is the exact image).
if [ -n "$tables" ]; then
  "$build/bin/havs_benchmark" --dump-case "$b/cases" --datasets "${datasets%%,*}" \
    --size "${sizes%%,*}" --cache-dir "$cache" --dump-kinds "$tables"
fi
for d in "$b"/cases/*/; do
  rm -f "$d"/{samples.f32,steps.f32,table_samples.i32,layers.f32,cpu_table_ms.txt}
  rm -f "$d"/{table.f32,points.f32,scalars.f32,indices.u32,tetrahedra.u32,mirrored.u32,order.u32} \
    "$d"/{cells.f32,boundary_faces.u32,boundary_cells.u32,neighbours.i32,result.f32}
done

# The cases of one data set and size share their exact image and mask: one
# copy, hard links (tar stores a link once).
declare -A seen
for f in "$b"/cases/*/reference.u16 "$b"/cases/*/folded.u8; do
  [ -f "$f" ] || continue
  sum=$(md5sum < "$f" | cut -d' ' -f1)
  if [ -n "${seen[$sum]:-}" ]; then
    ln -f "${seen[$sum]}" "$f"
  else
    seen[$sum]=$f
  fi
done

cp "$build/bin/havs_gpu_bench" "$build/bin/havs_gpu_cases" "$b/bin/"
# havs_gpu_cases' libraries: vtkHAVS::Core and the VTK modules it links.
ldd "$build/bin/havs_gpu_cases" | awk '/=> \// { print $3 }' | grep '/libvtk' |
  while read -r lib; do cp -L "$lib" "$b/lib/vtk/"; done
# libglvnd's EGL loader, used there only when the image has none.
for lib in libEGL.so.1 libGLdispatch.so.0; do
  path=$(ldconfig -p | awk -v n="$lib" '$1 == n && /x86-64/ { print $NF; exit }')
  if [ -n "$path" ]; then cp -L "$path" "$b/lib/glvnd/"; fi
done
cp "$here/run_gpu_bundle.sh" "$here/README.md" "$b/"
strip --strip-unneeded "$b"/bin/* "$b"/lib/vtk/* 2>/dev/null || true

tar -C "$stage" -cf - havs-gpu | xz -T2 -6 > "$out/havs-gpu-bundle.tar.xz"
size_of() { du -sb "$@" | awk '{ s += $1 } END { printf "%.1f", s / 1048576 }'; } # (links once)
xz_of() { tar -C "$b" -cf - "$@" | xz -T2 -6 | wc -c | awk '{ printf "%.1f", $1 / 1048576 }'; }
(
  cd "$b"
  echo "# havs-gpu-bundle.tar.xz: what it holds (MiB, raw / xz)"
  echo "made $(date -u +%Y-%m-%dT%H:%MZ) from $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?'), data sets $datasets, sizes $sizes"
  echo "| part | raw | xz |"
  echo "|---|---|---|"
  echo "| frame cases ($(ls -d cases/*/ | wc -l): shaders, uniforms, exact images, masks) | $(size_of cases/*/) | $(xz_of --exclude='*.havsmesh' cases) |"
  meshes=$(ls cases/*.havsmesh 2>/dev/null || true)
  if [ -n "$meshes" ]; then
    echo "| real meshes ($(echo $meshes | xargs -n1 basename | tr '\n' ' ')) | $(size_of $meshes) | $(xz_of $meshes) |"
  fi
  echo "| havs_gpu_bench, havs_gpu_cases | $(size_of bin) | $(xz_of bin) |"
  echo "| VTK and vtkHAVS::Core libraries ($(ls lib/vtk | wc -l)) | $(size_of lib/vtk) | $(xz_of lib/vtk) |"
  echo "| libglvnd (libEGL.so.1, libGLdispatch.so.0) | $(size_of lib/glvnd) | $(xz_of lib/glvnd) |"
  total=$(stat -c %s "$out/havs-gpu-bundle.tar.xz")
  echo "| **the bundle** | $(size_of .) | $(awk -v t="$total" 'BEGIN { printf "%.1f", t / 1048576 }') |"
  echo "made in $(($(date +%s) - t0)) s; limit ${limit} MiB"
) | tee "$out/bundle-size.txt"
total=$(stat -c %s "$out/havs-gpu-bundle.tar.xz")
if [ "$total" -gt $((limit * 1048576)) ]; then
  echo "make_gpu_bundle.sh: the bundle is $((total / 1048576)) MiB, over ${limit} MiB" >&2
  exit 1
fi
echo "wrote $out/havs-gpu-bundle.tar.xz"
