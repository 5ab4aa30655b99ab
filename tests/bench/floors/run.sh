#!/usr/bin/env bash
# The floors of the dense rows' double-double design (docs/benchmarks.md,
# "Floors, measured"): the dense benchmarks of this checkout's HEAD, and of the
# same code with the patches of this folder applied, one at a time:
#   seed_rows_without_trig.patch               the seed's rows with no sine or cosine;
#   seed_rows_trig_by_rotation.patch           ... with sine and cosine by a rotation;
#   oscillator_rows_without_transcendentals.patch  the general rows with none;
#   oscillator_rows_by_rotation.patch          ... with rotations and products.
# The patched binaries compute wrong values (made-up constants): they
# measure what the rest of a row costs, not a result. Each binary is run
# ROUNDS times (default 2), in turn, and the medians of each run printed in
# cos calls per sample, with each general case's ratio to the seed's sample
# of the same binary (paired as tests/bench/run.sh pairs them).
#   bash tests/bench/floors/run.sh    (from the repository's root; about 15 minutes)
set -euo pipefail
root=$(git rev-parse --show-toplevel)
here="$root/tests/bench/floors"
work=${FLOORS_WORK:-/tmp/frictionref-floors}
rounds=${ROUNDS:-2}
patches=(seed_rows_without_trig seed_rows_trig_by_rotation oscillator_rows_without_transcendentals
         oscillator_rows_by_rotation)

# A worktree left by an earlier run goes first (its registration with it).
git -C "$root" worktree remove -f "$work/tree" 2> /dev/null || true
git -C "$root" worktree prune
rm -rf "$work" && mkdir -p "$work/bin"
git -C "$root" worktree add -f --detach "$work/tree" HEAD > /dev/null
trap 'git -C "$root" worktree remove -f "$work/tree"' EXIT
cd "$work/tree"
cmake --preset release -DFRICTIONREF_BUILD_PYTHON=OFF > "$work/configure.log"
# Builds the benchmarks of the tree as it is and keeps them as bin/NAME; a
# failed build shows its log's end and stops the script.
build() {
  if ! cmake --build build/release -j2 --target frictionref_benchmarks > "$work/build-$1.log" 2>&1; then
    tail -n 30 "$work/build-$1.log" >&2
    echo "floors: the build of $1 failed (log: $work/build-$1.log)" >&2
    exit 1
  fi
  cp build/release/tests/bench/frictionref_benchmarks "$work/bin/$1"
}
echo "building HEAD ($(git rev-parse --short HEAD))" >&2
build head
for p in "${patches[@]}"; do
  echo "building HEAD + $p.patch" >&2
  git apply "$here/$p.patch"
  build "$p"
  git checkout -q -- .
done

filter='BM_StdCos|BM_DenseSamples|BM_GeneralDenseSamples'
for r in $(seq "$rounds"); do
  for b in head "${patches[@]}"; do
    echo "round $r: $b" >&2
    "$work/bin/$b" --benchmark_filter="$filter" --benchmark_repetitions=3 \
      --benchmark_report_aggregates_only=true --benchmark_out_format=json \
      --benchmark_out="$work/$b-$r.json" > /dev/null 2> "$work/$b-$r.err"
  done
done

python3 - "$work" "$rounds" head "${patches[@]}" << 'EOF'
import json, sys
work, rounds, binaries = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def medians(path):
    out = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") == "median" and "cos_calls_per_sample" in b:
            out[b["run_name"]] = b["cos_calls_per_sample"]
    return out
runs = {b: [medians(f"{work}/{b}-{r}.json") for r in range(1, rounds + 1)] for b in binaries}
names = list(runs["head"][0])
print("cos calls per sample (median of 3 repetitions), one column per run of each binary")
print()
print("| benchmark | " + " | ".join(binaries) + " |")
print("|---|" + "---:|" * len(binaries))
for n in names:
    cells = [", ".join(f"{m[n]:.2f}" for m in runs[b]) for b in binaries]
    print(f"| {n} | " + " | ".join(cells) + " |")
print()
print("each general case against the seed's sample of the same run, as tests/bench/run.sh pairs them")
print("(case 0 with BM_DenseSamples/70, the others with BM_DenseSamples/30)")
print()
print("| benchmark | " + " | ".join(binaries) + " |")
print("|---|" + "---:|" * len(binaries))
for n in names:
    if not n.startswith("BM_GeneralDenseSamples"):
        continue
    seed = "BM_DenseSamples/70" if n.endswith("/0") else "BM_DenseSamples/30"
    cells = [", ".join(f"{m[n] / m[seed]:.2f}x" for m in runs[b]) for b in binaries]
    print(f"| {n} | " + " | ".join(cells) + " |")
EOF
