#!/usr/bin/env bash
# The peer comparison: frictionref's exact engine against scipy solve_ivp, SUNDIALS CVODE
# and Siconos (and our stiff-spring simulator) on the same cases; writes
# docs/performance.md. See tests/peers/README.md.
#
# Usage (as root on Debian 12, from anywhere inside the repository):
#   bash tests/peers/run.sh
#
# Environment:
#   PEERS_DEADLINE        wall-clock limit of one run on a 30-unit case or a general-model
#                         case [s] (default 60)
#   PEERS_DEADLINE_1000P  wall-clock limit of one run on the 1000-period case [s] (default 60)
#   PEERS_KEEP=DIR        keep the raw results (one JSON per run) in DIR
#   PEERS_SKIP_APT=1      do not run apt-get (the packages are known to be there)
#   PEERS_BUILD_DIR=DIR   build the project in DIR (cmake -S . -B DIR, Release) instead of
#                         build/release through the preset (default: the preset)
#   PEERS_SOURCE=HEAD     build the project from the last commit (git archive HEAD, in a
#                         temporary directory) instead of the working tree, when others
#                         have uncommitted changes in it; the drivers in tests/peers still
#                         come from the working tree (default: the working tree)
#   PEERS_NOTE=TEXT       a paragraph for the report's machine section (e.g. other load)
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
build_dir=${PEERS_BUILD_DIR:-}
source_args=()
if [[ "${PEERS_SOURCE:-}" == HEAD ]]; then
  # The last commit, not the working tree: export it (read-only for git) and build it in a
  # temporary directory.
  mkdir -p "$tmp/source"
  printf '+ git archive HEAD | tar -x -C %s\n' "$tmp/source"
  printf 'git archive HEAD | tar -x -C %s\n' "$tmp/source" >>"$prelude"
  git -C "$repo" archive --format=tar HEAD | tar -x -C "$tmp/source"
  build_dir="$tmp/project"
  # Without the Python module: `cmake --install` would install it, and only the
  # library and the CLI are built here.
  run cmake -S "$tmp/source" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
    -DFRICTIONREF_BUILD_TESTS=OFF -DFRICTIONREF_BUILD_PYTHON=OFF
  run cmake --build "$build_dir" -j2 --target frictionref frictionref_cli
  source_args=(--source-head "$(git -C "$repo" rev-parse --short=12 HEAD)")
elif [[ -z "$build_dir" ]]; then
  build_dir=build/release
  if [[ ! -f build/release/CMakeCache.txt ]]; then
    run cmake --preset release
  fi
  run cmake --build --preset release -j2 --target frictionref frictionref_cli
else
  if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
    run cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DFRICTIONREF_BUILD_PYTHON=OFF
  fi
  run cmake --build "$build_dir" -j2 --target frictionref frictionref_cli
fi

# 3. Install to a temporary prefix; build the drivers against it.
run cmake --install "$build_dir" --prefix "$tmp/prefix"
run cmake -S tests/peers -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$tmp/prefix"
run cmake --build "$tmp/build" -j2

# 4. Run every peer on every case and write the report.
printf '%s\n' "${PEERS_NOTE:-}" >"$tmp/note.txt"
run "$python" tests/peers/run_all.py --bin "$tmp/build" --results "$tmp/results" \
  --doc "$doc_tmp" --repo "$repo" \
  --deadline "${PEERS_DEADLINE:-60}" --deadline-1000p "${PEERS_DEADLINE_1000P:-60}" \
  --tmp-prefix "$tmp" --prelude "$prelude" --script-start "$start_epoch" \
  ${PEERS_BUILD_DIR:+--build-dir "$build_dir"} "${source_args[@]}" --note-file "$tmp/note.txt"
mv -f "$doc_tmp" docs/performance.md

if [[ -n "${PEERS_KEEP:-}" ]]; then
  mkdir -p "$PEERS_KEEP"
  cp -r "$tmp/results/." "$PEERS_KEEP/"
  echo "results kept in $PEERS_KEEP"
fi
echo "wrote docs/performance.md in $(($(date +%s) - start_epoch)) s"
