#!/usr/bin/env bash
# instructions.sh [BIN] [N] -> Topple's instructions a step over steps 1..N (default 600), counted by
# callgrind: a run of N steps less a run of 1 step (the scene's set-up), over N - 1. The figure does not
# depend on the machine's load, unlike karma_topple's times. BIN defaults to the Release bench build's
# karma_topple (cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON).
set -euo pipefail
BIN=${1:-build/bench/bench/topple/karma_topple}
N=${2:-600}
count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$BIN" --rounds 1 --steps "$1" 2>&1 >/dev/null | awk '/Collected/ {print $4}'; }
one=$(count 1)
all=$(count "$N")
echo "topple steps 1-$N: $(( (all - one) / (N - 1) )) instructions a step"
