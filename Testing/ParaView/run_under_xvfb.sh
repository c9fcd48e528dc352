#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# Runs a command under a fresh Xvfb display (Debian's ParaView is GLX-only).
# X connections fail now and then here: a run that could not reach its
# display is retried (up to 3 times); any other failure is the test's.
set -u
for attempt in 1 2 3; do
  log=$(mktemp)
  # The output into the log first, then shown: with a tee in a process
  # substitution the grep below could run before the last lines (a pvserver's
  # X failure, printed at the end) reached the log, and a lost display was
  # then taken for the test's failure (seen once: ParaView.PluginServer).
  xvfb-run -a -s "-screen 0 1280x1024x24 -nolisten tcp" "$@" > "$log" 2>&1
  status=$?
  cat "$log"
  if [ $status -eq 0 ] || ! grep -qiE "cannot open display|Could not open display|xvfb-run: error|bad X server connection|failed to connect to X" "$log"; then
    rm -f "$log"
    exit $status
  fi
  echo "run_under_xvfb: X display failed (attempt $attempt), retrying" >&2
  rm -f "$log"
done
exit $status
