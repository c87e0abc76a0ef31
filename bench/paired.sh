#!/usr/bin/env bash
# paired.sh -- Karma against one peer on one scene, in alternating runs: the ratio of each pair's
# median CPU ms per step (Karma / peer), then the median of those ratios. On a shared VM whose speed
# drifts 30 % to 2x for minutes at a time, two runs seconds apart see about the same machine, so
# the paired ratio is steadier than a ratio of separate best rounds (bench/run.sh).
#
#   bash bench/paired.sh                           # pile, Karma default vs Bullet si10, 10 pairs
#   bash bench/paired.sh ragdolls ode quickstep20 6
#
# Arguments: SCENE (pile), PEER (bullet or ode), PEER_VARIANT (si10 / quickstep20), PAIRS (10);
# KARMA_VARIANT (environment, default "default"). Uses the binaries of bench/run.sh's build
# (BUILD, default build/bench), which it builds if needed.
set -euo pipefail
cd "$(dirname "$0")/.."

SCENE=${1:-pile}
PEER=${2:-bullet}
PAIRS=${4:-10}
KARMA_VARIANT=${KARMA_VARIANT:-default}
BUILD=${BUILD:-build/bench}
case "$PEER" in
bullet) PEER_VARIANT=${3:-si10} ;;
ode) PEER_VARIANT=${3:-quickstep20} ;;
*) echo "usage: bash bench/paired.sh [SCENE] [bullet|ode] [PEER_VARIANT] [PAIRS]" >&2; exit 2 ;;
esac
if ! [[ "$PAIRS" =~ ^[1-9][0-9]*$ ]]; then
    echo "paired.sh: PAIRS must be a positive number, not '$PAIRS'" >&2
    exit 2
fi
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
      -DKARMA_BUILD_TOOLS=OFF >/dev/null
cmake --build "$BUILD" --target karma_scenes "${PEER}_peer" >/dev/null

# median CPU ms per step of one run (column 9 of the scene line)
cpu_ms() { # program variant
    "$BUILD/bench/$1" --variants="$2" --scenes="$SCENE" 2>/dev/null | awk -F, -v v="$2" '$2 == v { print $9 }'
}
ratios=()
echo "Karma $KARMA_VARIANT against $PEER $PEER_VARIANT on $SCENE, $PAIRS alternating pairs (CPU ms per step, median of each run):"
for ((i = 1; i <= PAIRS; i++)); do
    k=$(cpu_ms karma_scenes "$KARMA_VARIANT") || k=""
    p=$(cpu_ms "${PEER}_peer" "$PEER_VARIANT") || p=""
    if [ -z "$k" ] || [ -z "$p" ]; then
        echo "paired.sh: a run printed no result (scene '$SCENE'?)" >&2
        exit 1
    fi
    r=$(awk -v k="$k" -v p="$p" 'BEGIN { printf "%.3f", k / p }')
    ratios+=("$r")
    echo "  pair $i: Karma $k  $PEER $p  ratio $r"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END {
    m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
    printf "median ratio %.3f (lowest %.3f, highest %.3f; below 1: Karma faster)\n", m, a[1], a[NR] }'
