#!/usr/bin/env bash
# Fetches the Stanford bunny (1,839 vertices, public domain) from the npm
# registry (`npm pack bunny@1.0.1`) and converts it to PLY (mesh) and XYZ
# (points only). Usage: Data/fetch-bunny.sh OUTDIR. Idempotent.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
out=${1:?usage: fetch-bunny.sh OUTDIR}
mkdir -p "$out"
if [ -s "$out/bunny.ply" ] && [ -s "$out/bunny.xyz" ]; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends npm >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack --silent bunny@1.0.1 >/dev/null && tar xzf bunny-1.0.1.tgz)
/usr/bin/python3 "$here/bunny_js_to_ply.py" "$work/package/index.js" "$out/bunny.ply" "$out/bunny.xyz"
