#!/usr/bin/env bash
# Runs a rendering test ("$@", e.g. xvfb-run ... pvpython TEST.py) again, at most three times in all,
# when and only when its render window could not connect to the virtual X server: VTK then aborts
# with "bad X server connection" before the test reaches its checks (seen about one run in ten,
# more on a loaded machine). Any other failure, an assertion included, is the test's result at once.
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
rc=1
for attempt in 1 2 3; do
  "$@" >"$log" 2>&1
  rc=$?
  cat "$log"
  if [ "$rc" -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    exit "$rc"
  fi
  echo "run-with-display.sh: attempt $attempt of 3 found no X server for its render window" >&2
  sleep 2
done
exit "$rc"
