#!/usr/bin/env bash
# Instructions per phase of `frictionref events` on the three models of
# BM_GeneralEvents (tests/bench/bench_general_events.cpp), counted by
# valgrind's callgrind over 1250 and 2500 forcing periods; the difference
# divided by the difference in phases leaves out start-up. A deterministic
# figure beside the benchmark's wall-clock one (docs/benchmarks.md).
# (Only for the general engine: valgrind computes long double in 64 bits,
# which the seed's path does not survive.)
#   bash tests/bench/general_instructions.sh [BINARY]   (default build/release/frictionref)
set -euo pipefail
B=${1:-build/release/frictionref}
command -v valgrind > /dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 2; }
models=("--friction 0.7 --static-friction 0.7000000000000001" "--friction 0.4 --static-friction 0.6 --stiffness 1 --damping 0.1" "--friction 0.3 --stiffness 1 --damping 0.05 --harmonic 0.4,2.5,0.3")
for i in 0 1 2; do
  m=${models[$i]}
  cnt() { valgrind --tool=callgrind --callgrind-out-file=/dev/null $B events $m --t-end $1 --summary 2>&1 | grep refs | awk '{gsub(",","",$4); print $4}'; }
  ph() { $B events $m --t-end $1 --summary | tr ' ' '\n' | grep "^phases=" | cut -d= -f2; }
  a=$(cnt 7853.981633974483); b=$(cnt 15707.963267948966)
  pa=$(ph 7853.981633974483); pb=$(ph 15707.963267948966)
  echo "case $i: $(( (b - a) / (pb - pa) )) instructions per phase ($pa, $pb phases)"
done
