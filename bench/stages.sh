#!/usr/bin/env bash
# stages.sh -- how much of Karma's step runs on the workers, counted in instructions (callgrind), and
# the wall speed-up that bounds (issue 17, point 5). Instructions, not time: the figure is the same on a
# loaded machine, where bench/threads.sh's wall times are not.
#
#   bash bench/stages.sh                      # ragdolls and pile, nosleep, 120 steps, bound at 2 threads
#   bash bench/stages.sh "ragdolls pile" 300 4
#
# Each scene runs twice under callgrind, collecting only the step (karma_step) and the pool's helper
# threads (helperMain): once on one thread (T1, the serial step) and once on a pool of 2 (T2, all
# threads summed). In the threaded run W is what ran inside the step's tasks (markedTask: prediction,
# rows, solves, integration, unpack, the bridge's pair tests and, beside the next chunk's tests, its
# conversion of a chunk into contacts: pipelineItems) and S = T2 - W the rest (the partition
# search, farfield, the last chunk's conversion, moving rows, gathering, the pool's hand-outs; not the pool's
# threads spinning for the next task or for the last ranges, `spinUntil`, which is waiting, taken out
# of T2). On N workers a
# step takes at least S + W/N, and at least S + the largest single item (one partition's solve):
# the bound printed is T1 / max(S + W/N, S + solves + (W - solves)/N), the second only for a scene
# whose solve is one partition (the pile's heap; SINGLE_PARTITION=yes|no overrides the guess from the
# name), since one partition is one item.
#
# A split partition (KARMA_SPLIT_ROWS) runs as one task whose helpers spin between its stages, which
# callgrind counts as work: for it use bench/split_share.sh.
#
# Arguments: SCENES ("ragdolls pile"), STEPS (120), THREADS for the bound (2); KARMA_VARIANT
# (environment, default nosleep). Uses BUILD (default build/bench), built if needed.
set -euo pipefail
cd "$(dirname "$0")/.."

SCENES=${1:-ragdolls pile}
STEPS=${2:-120}
THREADS=${3:-2}
KARMA_VARIANT=${KARMA_VARIANT:-nosleep}
BUILD=${BUILD:-build/bench}
command -v valgrind >/dev/null || { echo "stages.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
      -DKARMA_BUILD_TOOLS=OFF >/dev/null
cmake --build "$BUILD" --target karma_scenes >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# inclusive instructions of function $2 in callgrind output $1 (0 if absent)
inclusive() {
    callgrind_annotate --inclusive=yes --threshold=100 "$1" 2>/dev/null |
        awk -v f="$2" '{ gsub(",", "", $1) } !found && $0 ~ (":" f "( |$)") { value = $1; found = 1 } END { print found ? value : 0 }'
}

run() { # scene threads out
    valgrind --tool=callgrind --callgrind-out-file="$3" --toggle-collect=karma_step --toggle-collect=helperMain \
        "$BUILD/bench/karma_scenes" --variants="$KARMA_VARIANT" --scenes="$1" --steps="$STEPS" --threads="$2" \
        >/dev/null 2>&1
}

printf "%-10s %14s %14s %14s %14s %8s %8s %10s\n" scene "T1/step" "T2/step" "W(tasks)" "solves" "W/T2" "S/T2" "bound@$THREADS"
for scene in $SCENES; do
    run "$scene" 1 "$work/one.out"
    run "$scene" 2 "$work/two.out"
    t1=$(callgrind_annotate "$work/one.out" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }')
    t2=$(callgrind_annotate "$work/two.out" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }')
    t2=$((t2 - $(inclusive "$work/two.out" spinUntil)))
    w=$(inclusive "$work/two.out" markedTask)
    solves=$(inclusive "$work/two.out" solveTask)
    awk -v s="$scene" -v t1="$t1" -v t2="$t2" -v w="$w" -v sv="$solves" -v n="$THREADS" -v steps="$STEPS" \
        -v single="${SINGLE_PARTITION:-auto}" 'BEGIN {
        serial = t2 - w
        span = serial + w / n
        if ((single == "auto" && s ~ /^pile/) || single == "yes") {
            one = serial + sv + (w - sv) / n  # the one partition'"'"'s solve is a single item
            if (one > span) span = one
        }
        printf "%-10s %14.0f %14.0f %14.0f %14.0f %7.1f%% %7.1f%% %9.2fx\n", s, t1 / steps, t2 / steps, w / steps,
               sv / steps, 100 * w / t2, 100 * serial / t2, t1 / span
    }'
    # W by stage: what each task's items cost per step (pair tests: the bridge's, through MdtWorldRunTask)
    line="  by stage per step:"
    for f in predictTask packTask solveTask integrateTask unpackTask testPairs pipelineItems; do
        v=$(inclusive "$work/two.out" "$f")
        line="$line $f $((v / STEPS))"
    done
    echo "$line"
done
echo "(instructions per step over $STEPS steps from the start, Karma $KARMA_VARIANT; the bound is an upper bound:"
echo " it assumes the tasks' work divides evenly and the hand-outs cost nothing but their instructions)"
