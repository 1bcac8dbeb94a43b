#!/usr/bin/env bash
# Runs a ParaView program (pvpython) under its own virtual X server, for the test paraview_plugin:
#   offscreen.sh PROGRAM ARGS...
# The server (Xvfb, without access control: it is private to the test and lives as long as it) gets
# the first free display from 187 on, away from the other tests' 99, which may run at the same time;
# the program starts once the server's socket is there, and a server that dies is reported.
# -noreset: without it Xvfb resets when its last client leaves, and ParaView, which connects, leaves
# and connects again when it opens its first render window, was refused about one run in four
# ("bad X server connection") when its second connection met the reset (xvfb-run does the same).
set -u
display=187
while [ -e "/tmp/.X${display}-lock" ] || [ -e "/tmp/.X11-unix/X${display}" ]; do display=$((display + 1)); done
Xvfb ":${display}" -screen 0 1024x768x24 -ac -noreset -nolisten tcp > "/tmp/prstar_xvfb_${display}.log" 2>&1 &
server=$!
trap 'kill $server 2> /dev/null; wait $server 2> /dev/null; rm -f "/tmp/prstar_xvfb_${display}.log"' EXIT
for _ in $(seq 1 100); do
  if [ -S "/tmp/.X11-unix/X${display}" ]; then sleep 0.2; break; fi
  if ! kill -0 $server 2> /dev/null; then
    echo "offscreen.sh: Xvfb :${display} did not start:"; cat "/tmp/prstar_xvfb_${display}.log"; exit 1
  fi
  sleep 0.1
done
DISPLAY=":${display}" "$@"
status=$?
if ! kill -0 $server 2> /dev/null; then
  echo "offscreen.sh: Xvfb :${display} died during the run:"; cat "/tmp/prstar_xvfb_${display}.log"
fi
exit $status
