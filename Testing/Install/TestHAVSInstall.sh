#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# The install, as an outside project meets it: `cmake --install` into a fresh
# prefix, then, against that prefix only,
#   - the installed files are there (libraries, headers, CMake package, apps,
#     Python package, ParaView plugin, expat fix);
#   - an outside CMake project (consumer/) configures with find_package(vtkHAVS),
#     builds, and its program renders a non-empty image with vtkHAVSVolumeMapper;
#   - the control: the same project against an empty prefix fails to configure;
#   - python3 with only the prefix's package directory on PYTHONPATH imports
#     vtkhavs and renders (havs_consumer.py);
#   - the installed apps run, and pvpython finds the plugin through PV_PLUGIN_PATH.
# Arguments: BUILD_DIR SOURCE_DIR PYTHON_DESTINATION [PVPYTHON]
set -u
build=$1 source=$2 pydest=$3 pvpython=${4:-}
work=$(mktemp -d /tmp/havs-install.XXXXXX)
prefix=$work/prefix empty=$work/empty
mkdir -p "$empty"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }
# Nothing of the build tree may leak in: no build paths in the environment.
unset LD_LIBRARY_PATH PYTHONPATH LD_PRELOAD VTK_DIR ParaView_DIR
cmake_args=(-G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)

echo "== cmake --install $build --prefix $prefix"
if cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1; then
  ok "cmake --install ($(grep -c Installing "$work/install.log") files)"
else
  cat "$work/install.log"; fail "cmake --install"
fi
for f in lib/cmake/vtkHAVS/vtkHAVSConfig.cmake lib/cmake/vtkHAVS/vtkHAVSConfigVersion.cmake \
    lib/cmake/vtkHAVS/vtkHAVS-targets.cmake include/vtkHAVS/vtkHAVSVolumeMapper.h \
    bin/havs_demo bin/havs_reference bin/havs_benchmark bin/havs_gpu_bench bin/havs_view \
    lib/libvtkHAVSExpatFix.so \
    lib/paraview-plugins/HAVSRepresentation/HAVSRepresentation.so \
    "$pydest/vtkhavs/__init__.py" share/doc/vtkHAVS/LICENSE; do
  [ -e "$prefix/$f" ] && ok "installed $f" || fail "not installed: $f"
done

echo "== outside project against the prefix only"
if cmake -S "$source/Testing/Install/consumer" -B "$work/consumer" "${cmake_args[@]}" \
    -DCMAKE_PREFIX_PATH="$prefix" > "$work/consumer.log" 2>&1; then
  grep "vtkHAVS " "$work/consumer.log"
  ok "find_package(vtkHAVS) against the prefix"
  if cmake --build "$work/consumer" > "$work/consumer-build.log" 2>&1; then
    ok "the outside project builds"
    if "$work/consumer/havs_consumer"; then ok "havs_consumer renders"; else fail "havs_consumer"; fi
  else
    tail -30 "$work/consumer-build.log"; fail "the outside project does not build"
  fi
else
  cat "$work/consumer.log"; fail "the outside project does not configure against the prefix"
fi

echo "== control: the same project against an empty prefix"
if cmake -S "$source/Testing/Install/consumer" -B "$work/control" "${cmake_args[@]}" \
    -DCMAKE_PREFIX_PATH="$empty" > "$work/control.log" 2>&1; then
  fail "control: the outside project configured without vtkHAVS installed"
else
  grep -m1 -E "vtkHAVS" "$work/control.log"
  ok "control: without the install, find_package(vtkHAVS) fails"
fi

echo "== Python, the prefix's package only"
if PYTHONPATH="$prefix/$pydest" /usr/bin/python3 "$source/Testing/Install/havs_consumer.py"; then
  ok "import vtkhavs from the prefix and render"
else
  fail "the installed Python package"
fi

echo "== installed apps"
if "$prefix/bin/havs_reference" --help > /dev/null 2>&1 && "$prefix/bin/havs_demo" --help > /dev/null 2>&1 \
    && "$prefix/bin/havs_view" --help > /dev/null 2>&1; then
  ok "havs_reference --help, havs_demo --help, havs_view --help"
else
  fail "an installed app does not start"
fi
if ldd "$prefix/bin/havs_demo" | grep -q "$build"; then
  fail "havs_demo links the build tree"
fi

if [ -n "$pvpython" ] && command -v Xvfb > /dev/null; then
  echo "== ParaView finds the installed plugin through PV_PLUGIN_PATH"
  cat > "$work/plugin.py" <<'PY'
from paraview.simple import Delaunay3D, Show, Sphere
import sys
display = Show(Delaunay3D(Input=Sphere()))
available = display.GetProperty("Representation").Available
print("representations:", ", ".join(available))
sys.exit(0 if "HAVS Volume" in available else 1)
PY
  PV_PLUGIN_PATH="$prefix/lib/paraview-plugins/HAVSRepresentation" \
    LD_PRELOAD="$prefix/lib/libvtkHAVSExpatFix.so" \
    "$source/Testing/ParaView/run_under_xvfb.sh" "$pvpython" "$work/plugin.py" > "$work/plugin.log" 2>&1
  status=$?
  grep "representations:" "$work/plugin.log" || tail -20 "$work/plugin.log"
  [ $status -eq 0 ] && ok "pvpython shows HAVS Volume from the installed plugin" \
    || fail "pvpython does not find the installed plugin"
fi

rm -rf "$work"
if [ $failures -gt 0 ]; then
  echo "TestHAVSInstall: $failures FAILED"
  exit 1
fi
echo "TestHAVSInstall: PASSED"
