#!/usr/bin/env bash
# Writes the seed corpus of fuzz_shard_merge (tests/fuzz/corpus/shard_merge/):
# real shard sets of sweep and map, each set's files joined by a 0xFF byte
# (the fuzz target's file separator), plus a few broken sets.
# Usage: tests/fuzz/tools/make_shard_seeds.sh [path/to/frictionref]
set -euo pipefail
cd "$(dirname "$0")/../../.."
frictionref=$(realpath "${1:-build/release/frictionref}")
out=tests/fuzz/corpus/shard_merge
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# seed NAME N STUDY...: the N shards of STUDY joined, in reverse order.
seed() {
  local name=$1 count=$2
  shift 2
  local files=()
  for ((i = count; i >= 1; --i)); do
    # In the scratch directory, so that '# command:' has no temporary path.
    (cd "$work" && "$frictionref" "$@" --shard "$i/$count" -o "$name-$i.csv")
    files+=("$work/$name-$i.csv")
  done
  : > "$out/$name"
  local first=1
  for f in "${files[@]}"; do
    ((first)) || printf '\xff' >> "$out/$name"
    first=0
    cat "$f" >> "$out/$name"
  done
}

seed sweep-seed-3 3 sweep --lambda-from 0 --lambda-to 1.2 --points 7 --periods 5
seed sweep-den-hartog-2 2 sweep --lambda-from 0.1 --lambda-to 0.5 --points 4 --stiffness 1 --omega 2 --periods 5
seed sweep-general-2 2 sweep --lambda-from 0 --lambda-to 1 --points 3 --static-ratio 1.5 --stiffness 1 --damping 0.1 --harmonic 0.3,3 --periods 5
seed sweep-empty-shards-4 4 sweep --lambda-from 0.2 --lambda-to 0.8 --points 2 --periods 3
seed map-3 3 map --x lambda:0.1:0.5:2 --y frequency-ratio:0.5:2:2 --stiffness 1 --periods 5
seed map-1 1 map --x lambda:0.1:0.5:2 --y omega:1:2:2 --periods 5
# Broken sets: a shard missing, a shard cut short.
head -c "$(($(grep -boa $'\xff' "$out/sweep-seed-3" | head -1 | cut -d: -f1)))" \
  "$out/sweep-seed-3" > "$out/broken-missing-shard"
head -c 400 "$out/map-3" > "$out/broken-truncated"
ls "$out"
