#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# Makes Documentation/images/paraview_havs.png: the ParaView client (under
# Xvfb) with the vtkHAVS plugin loaded, the LOX post shown as "HAVS Volume"
# and the HAVS properties in the panel. Needs a build (bash .ci/build) and
# x11-apps (xwd), installed here when missing.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
if ! command -v xwd > /dev/null; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get install -y -qq x11-apps > /dev/null
fi
plugin=$(find "$root/build/lib/paraview-plugins" -name "HAVSRepresentation.so" | head -1)
data=${HAVS_DATA_DIR:-$root/../shared/data}
work=$(mktemp -d)
cat > "$work/show.py" <<PY
from paraview.simple import *
LoadPlugin("$plugin", remote=False, ns=globals())
reader = LegacyVTKReader(FileNames=["$data/post.vtk"])
tets = Tetrahedralize(Input=reader)
view = GetActiveViewOrCreate("RenderView")
display = Show(tets, view)
ColorBy(display, ("POINTS", "Pressure"))
display.Representation = "HAVS Volume"
display.HAVSKBufferSize = 8
GetOpacityTransferFunction("Pressure").Points = [0.0, 0.0, 0.5, 0.0, 1.0, 0.6, 0.5, 0.0]
GetOpacityTransferFunction("Pressure").RescaleTransferFunction(
    *tets.PointData["Pressure"].GetRange())
view.ResetCamera()
SetActiveSource(tets)
Render()
PY
# A fresh settings directory without the welcome dialog; with
# HAVS_SCREENSHOT_ADVANCED=1 the panel's advanced properties shown (the gear
# button's setting, showAdvancedProperties), written to paraview_havs_advanced.png.
mkdir -p "$work/config/ParaView"
out=paraview_havs.png
advanced=false
if [ "${HAVS_SCREENSHOT_ADVANCED:-0}" = 1 ]; then
  out=paraview_havs_advanced.png
  advanced=true
fi
printf '[General]\nGeneralSettings.ShowWelcomeDialog=0\nshowAdvancedProperties=%s\n' "$advanced" \
  > "$work/config/ParaView/ParaView5.11.0.ini"
display=:$((90 + RANDOM % 9))
height=1400
[ "$advanced" = true ] && height=${HAVS_SCREENSHOT_HEIGHT:-4400}
Xvfb "$display" -screen 0 1600x${height}x24 -nolisten tcp &
xvfb=$!
trap 'kill $xvfb 2> /dev/null || true; rm -rf "$work"' EXIT
sleep 2
# As the user guide says: the expat fix preloaded (Debian 12's expat defers
# reparsing, which VTK 9.2's XML readers cannot take; the plugin warns otherwise).
preload=""
[ -f "$root/build/lib/libvtkHAVSExpatFix.so" ] && preload="$root/build/lib/libvtkHAVSExpatFix.so"
DISPLAY=$display XDG_CONFIG_HOME="$work/config" LD_LIBRARY_PATH="$root/build/lib" LD_PRELOAD="$preload" paraview -geometry 1600x${height}+0+0 --script="$work/show.py" &
client=$!
sleep "${HAVS_SCREENSHOT_WAIT:-40}"
DISPLAY=$display xwd -root -silent > "$work/screen.xwd"
kill $client 2> /dev/null || true
# The advanced view: the panel's lower part (the HAVS group at the bottom of a
# 4400-pixel-high window), 300 x 1100 pixels.
crop=""
[ "$advanced" = true ] && crop="0,$((height - 1100)),300,1100"
pvpython "$root/Documentation/xwd_to_png.py" "$work/screen.xwd" \
  "$root/Documentation/images/$out" $crop
echo "wrote Documentation/images/$out"
