#!/bin/sh
# Runs a command against a virtual X server of its own: headless.sh COMMAND [ARGS...]
# Debian's ParaView draws through X11 (no EGL or OSMesa build), so its screenshots need an X
# server; Xvfb is one in memory. Two traps, both seen on the shared build machine:
# - a client that connects before the server is up fails ("bad X server connection"): -displayfd
#   makes Xvfb write the display number only once it accepts connections;
# - X clients try the display's abstract socket first, and abstract sockets are shared by every
#   process of the network namespace, containers included: on :0 or xvfb-run's :99 a client can
#   reach another user's server and be refused. So the display is a random one in 200-999,
#   retried when Xvfb finds it taken.
# The server is stopped when the command ends; the command's exit status is returned.
set -u
dir=$(mktemp -d)
xvfb=
trap '[ -n "$xvfb" ] && kill $xvfb 2>/dev/null; wait 2>/dev/null; rm -rf "$dir"' EXIT
for attempt in 1 2 3 4 5 6 7 8; do
  display=$(( ($$ * 7919 + $(date +%N | sed 's/^0*//;s/^$/0/') / 1000 + attempt * 131) % 800 + 200 ))
  : > "$dir/display"
  Xvfb ":$display" -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$dir/display" \
    2>"$dir/xvfb.log" &
  xvfb=$!
  tries=0
  while [ ! -s "$dir/display" ] && kill -0 $xvfb 2>/dev/null && [ $tries -lt 600 ]; do
    tries=$((tries + 1))
    sleep 0.1
  done
  [ -s "$dir/display" ] && break
  kill $xvfb 2>/dev/null
  wait $xvfb 2>/dev/null
  xvfb=
done
if [ -z "$xvfb" ]; then
  echo "headless.sh: Xvfb did not start; its last log:" >&2
  cat "$dir/xvfb.log" >&2
  exit 1
fi
DISPLAY=":$(cat "$dir/display")" "$@"
status=$?
if [ $status -ne 0 ]; then
  echo "headless.sh: the command failed ($status) on display :$(cat "$dir/display"); Xvfb log:" >&2
  cat "$dir/xvfb.log" >&2
fi
exit $status
