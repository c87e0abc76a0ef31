#!/usr/bin/env bash
# threads.sh -- wall-clock speed-up of the threaded step (issue 17, point 5): karma_scenes at 1 and at
# N threads (--threads, MeThreadPool) in alternating runs on each scene, the ratio of each pair's
# median wall ms per step (1 thread / N threads), then the median of those ratios. Wall time, not CPU
# time: threads spend more CPU to take less wall time. Two runs seconds apart see about the same
# machine; on a loaded machine the second thread may simply not get a core, so the load average is
# printed before and after: rerun on an idle machine for the figure that counts.
#
#   bash bench/threads.sh                        # ragdolls and pile, nosleep, 1 vs 2 threads, 5 pairs
#   bash bench/threads.sh "ragdolls pile" 2 8 300
#
# Arguments: SCENES ("ragdolls pile"), THREADS (2), PAIRS (5), STEPS (300; each run's step count);
# KARMA_VARIANT (environment, default nosleep: every body awake); KARMA_SPLIT_ROWS (environment,
# default 2000; empty: off) splits every iterative partition of that many rows over the threads
# (MdtWorldSetPartitionSplitRows: the pile's heap), in both runs of a pair. Uses BUILD (default
# build/bench), which it builds if needed.
#
# STEP_MIN=1 (environment) measures differently, for a loaded machine: each of the PAIRS rounds runs
# both thread counts with every step's wall time (--step-times); a step does the same work in every
# run (the trajectories are the same), so each step's fastest run over the rounds is what it costs
# when the other threads of the machine left it alone; the figure is the sum of those minima at 1
# thread over their sum at N threads. It tends to the idle machine's ratio as the rounds grow, but
# is no substitute for it.
set -euo pipefail
cd "$(dirname "$0")/.."

SCENES=${1:-ragdolls pile}
THREADS=${2:-2}
PAIRS=${3:-5}
STEPS=${4:-300}
KARMA_VARIANT=${KARMA_VARIANT:-nosleep}
export KARMA_SPLIT_ROWS=${KARMA_SPLIT_ROWS-2000}
BUILD=${BUILD:-build/bench}
for n in "$THREADS" "$PAIRS" "$STEPS"; do
    if ! [[ "$n" =~ ^[1-9][0-9]*$ ]]; then
        echo "usage: bash bench/threads.sh [SCENES] [THREADS] [PAIRS] [STEPS] (positive numbers)" >&2
        exit 2
    fi
done
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
      -DKARMA_BUILD_TOOLS=OFF >/dev/null
cmake --build "$BUILD" --target karma_scenes >/dev/null

# median wall ms per step of one run (column 7), and the run's quality figure (column 12)
run() { # scene threads
    "$BUILD/bench/karma_scenes" --variants="$KARMA_VARIANT" --scenes="$1" --steps="$STEPS" --threads="$2" \
        2>/dev/null | awk -F, -v v="$KARMA_VARIANT" '$2 == v { print $7, $12 }'
}
load1() { cut -d' ' -f1 /proc/loadavg; } # the 1-minute load average, beside each pair
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

echo "load before: $(uptime | sed 's/.*load average/load average/'); $(nproc) cores"
if [ "${STEP_MIN:-0}" = 1 ]; then
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    for scene in $SCENES; do
        for ((i = 1; i <= PAIRS; i++)); do
            for t in 1 "$THREADS"; do
                "$BUILD/bench/karma_scenes" --variants="$KARMA_VARIANT" --scenes="$scene" --steps="$STEPS" \
                    --threads="$t" --step-times 2>&1 >/dev/null | awk '$1 == "step" { print $2, $6 }' >"$tmp/$t.$i"
            done
        done
        # per step, the fastest of the rounds; then the sums
        one=$(cat "$tmp"/1.* | awk '{ if (!($1 in m) || $2 < m[$1]) m[$1] = $2 } END { for (k in m) s += m[k]; printf "%.4f", s / length(m) }')
        many=$(cat "$tmp"/"$THREADS".* | awk '{ if (!($1 in m) || $2 < m[$1]) m[$1] = $2 } END { for (k in m) s += m[k]; printf "%.4f", s / length(m) }')
        echo "$scene, Karma $KARMA_VARIANT, $STEPS steps, $PAIRS rounds: mean over steps of each step's fastest wall ms:" \
             "1 thread $one, $THREADS threads $many, speed-up $(awk -v a="$one" -v b="$many" 'BEGIN { printf "%.3f", a / b }')" \
             "(load $(load1))"
    done
    echo "load after: $(uptime | sed 's/.*load average/load average/')"
    exit 0
fi
for scene in $SCENES; do
    ratios=()
    echo "$scene, Karma $KARMA_VARIANT, $STEPS steps, 1 vs $THREADS threads, $PAIRS alternating pairs (median wall ms per step):"
    for ((i = 1; i <= PAIRS; i++)); do
        read -r one q1 < <(run "$scene" 1)
        read -r many qn < <(run "$scene" "$THREADS")
        if [ "$q1" != "$qn" ]; then
            echo "  pair $i: the quality figure differs ($q1 at 1 thread, $qn at $THREADS): not the same trajectory" >&2
            exit 1
        fi
        ratio=$(awk -v a="$one" -v b="$many" 'BEGIN { printf "%.3f", a / b }')
        ratios+=("$ratio")
        echo "  pair $i: 1 thread $one ms, $THREADS threads $many ms, speed-up $ratio (figure $q1 both; load $(load1))"
    done
    echo "  median speed-up on $scene: $(printf '%s\n' "${ratios[@]}" | median)"
done
echo "load after: $(uptime | sed 's/.*load average/load average/')"
