#!/usr/bin/env bash
# Copyright (c) 2026 the vtkHAVS developers. SPDX-License-Identifier: BSD-3-Clause (see LICENSE)
# Runs a command under a fresh Xvfb display (Debian's ParaView is GLX-only) and
# leaves nothing running behind it: the Xvfb is started here (not by
# xvfb-run, whose server outlived a killed test in a Debian 13 root and kept
# the root's /dev busy), the command runs in a process group of its own, and
# on any exit -- the command's end, ctest's timeout (SIGTERM), Ctrl-C -- that
# whole group (pvserver ranks, mpiexec's children) and the Xvfb are ended.
# X connections fail now and then here: a run that could not reach its
# display is retried (up to 3 times); any other failure is the test's.
set -u
xvfb_pid=""
group=""
cleanup() {
  if [ -n "$group" ]; then
    kill -TERM -- "-$group" 2> /dev/null
    for _ in 1 2 3 4 5 6 7 8 9 10; do
      kill -0 -- "-$group" 2> /dev/null || break
      sleep 0.2
    done
    kill -KILL -- "-$group" 2> /dev/null
    group=""
  fi
  if [ -n "$xvfb_pid" ]; then
    kill -TERM "$xvfb_pid" 2> /dev/null
    wait "$xvfb_pid" 2> /dev/null
    xvfb_pid=""
  fi
}
trap 'cleanup; exit 143' TERM
trap 'cleanup; exit 130' INT
trap cleanup EXIT

# start_xvfb: a new Xvfb on the first free display (-displayfd), DISPLAY set.
start_xvfb() {
  local fifo
  fifo=$(mktemp -u)
  mkfifo "$fifo"
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3> "$fifo" > /dev/null 2>&1 &
  xvfb_pid=$!
  local display=""
  read -r -t 30 display < "$fifo"
  rm -f "$fifo"
  if [ -z "$display" ]; then
    echo "run_under_xvfb: Xvfb did not start (Xvfb from Debian's xvfb package?)" >&2
    return 1
  fi
  export DISPLAY=":$display"
}

status=1
for attempt in 1 2 3; do
  log=$(mktemp)
  if start_xvfb; then
    # The output into the log first, then shown: the grep below must see the
    # last lines (a pvserver's X failure, printed at the end).
    setsid "$@" > "$log" 2>&1 &
    group=$!
    wait "$group"
    status=$?
  else
    echo "Could not open display: Xvfb failed to start" > "$log"
    status=1
  fi
  cleanup
  cat "$log"
  if [ $status -eq 0 ] || ! grep -qiE "cannot open display|Could not open display|bad X server connection|failed to connect to X" "$log"; then
    rm -f "$log"
    exit $status
  fi
  echo "run_under_xvfb: X display failed (attempt $attempt), retrying" >&2
  rm -f "$log"
done
exit $status
