#!/usr/bin/env bash
# The peer comparison: frictionref's exact engine against scipy solve_ivp, SUNDIALS CVODE
# and Siconos (and our stiff-spring simulator) on the same cases; writes
# docs/performance.md. See tests/peers/README.md.
#
# Usage (as root on Debian 12, from anywhere inside the repository):
#   bash tests/peers/run.sh
#
# Environment:
#   PEERS_DEADLINE        wall-clock limit of one run on a 30-unit case [s] (default 60)
#   PEERS_DEADLINE_1000P  wall-clock limit of one run on the 1000-period case [s] (default 60)
#   PEERS_KEEP=DIR        keep the raw results (one JSON per run) in DIR
#   PEERS_SKIP_APT=1      do not run apt-get (the packages are known to be there)
#
# Steps: installs the Debian packages (the project's own through .ci/install-deps, then
# python3-scipy, python3-siconos, libsundials-dev); builds the project if needed
# (cmake --preset release); installs it to a temporary prefix; builds the drivers in
# tests/peers as a standalone CMake project against it (find_package(frictionref));
# runs every peer on every case (run_all.py, about 5 minutes on 2 cores); writes the
# report to a temporary file in docs/ and moves it over docs/performance.md.
set -euo pipefail

start_epoch=$(date +%s)
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
cd "$repo"

# Debian's Python: a python3 earlier on PATH (pyenv) lacks the Debian modules.
python=/usr/bin/python3

tmp=$(mktemp -d /tmp/frictionref-peers.XXXXXX)
doc_tmp="$repo/docs/.performance.md.tmp"
cleanup() { rm -rf "$tmp"; rm -f "$doc_tmp"; }
trap cleanup EXIT

prelude="$tmp/prelude.txt"  # the commands, for the report
: >"$prelude"
run() {
  printf '+ %s\n' "$*"
  printf '%s\n' "$*" >>"$prelude"
  "$@"
}

# 1. Packages (Debian only; no pip).
if [[ "${PEERS_SKIP_APT:-0}" != 1 ]]; then
  run bash .ci/install-deps
  export DEBIAN_FRONTEND=noninteractive
  run apt-get update -qq
  run apt-get install -y -qq --no-install-recommends \
    python3-scipy python3-numpy python3-siconos libsundials-dev util-linux
fi

# 2. The project: configure once, build the library and the CLI (they are what gets
#    installed; the tests are not needed).
if [[ ! -f build/release/CMakeCache.txt ]]; then
  run cmake --preset release
fi
run cmake --build --preset release -j2 --target frictionref frictionref_cli

# 3. Install to a temporary prefix; build the drivers against it.
run cmake --install build/release --prefix "$tmp/prefix"
run cmake -S tests/peers -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$tmp/prefix"
run cmake --build "$tmp/build" -j2

# 4. Run every peer on every case and write the report.
run "$python" tests/peers/run_all.py --bin "$tmp/build" --results "$tmp/results" \
  --doc "$doc_tmp" --repo "$repo" \
  --deadline "${PEERS_DEADLINE:-60}" --deadline-1000p "${PEERS_DEADLINE_1000P:-60}" \
  --tmp-prefix "$tmp" --prelude "$prelude" --script-start "$start_epoch"
mv -f "$doc_tmp" docs/performance.md

if [[ -n "${PEERS_KEEP:-}" ]]; then
  mkdir -p "$PEERS_KEEP"
  cp -r "$tmp/results/." "$PEERS_KEEP/"
  echo "results kept in $PEERS_KEEP"
fi
echo "wrote docs/performance.md in $(($(date +%s) - start_epoch)) s"
