#!/usr/bin/env bash
# perturbed.sh [BIN] [N] [K...] -> Topple's instructions a step over steps 1..N (default 600) for each
# perturbation K (default 0 1 2 3 4: gravity scaled by 1 + K 1e-6, karma_topple --perturb), and their
# mean. A build that changes the solver's rounding runs the scene down another chaotic path, whose
# count differs from the first build's by as much as the perturbations' spread: compare means.
set -euo pipefail
BIN=${1:-build/bench/bench/topple/karma_topple}
N=${2:-600}
shift $(( $# > 2 ? 2 : $# ))
KS=${*:-0 1 2 3 4}
count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$BIN" --rounds 1 --steps "$1" --perturb "$2" 2>&1 >/dev/null | awk '/Collected/ {print $4}'; }
sum=0; n=0; line=""
for k in $KS; do
    one=$(count 1 "$k"); all=$(count "$N" "$k")
    v=$(( (all - one) / (N - 1) ))
    line="$line K=$k:$v"; sum=$(( sum + v )); n=$(( n + 1 ))
done
echo "topple steps 1-$N:$line mean $(( sum / n )) instructions a step"
