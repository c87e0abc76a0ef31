#!/usr/bin/env bash
# split_share.sh -- how much of the pile's step runs on the workers once its one large partition is split
# (MdtWorldSetPartitionSplitRows, issue 17 point 5), counted in instructions (callgrind) on ONE thread, where
# every task's items run inline and show as functions of their own: the Mdt stages' tasks (as bench/stages.sh
# counts them) plus the split solve's chunked loops (the sweep's colours, SM's loops and scatter). The rest of
# the step (the partition search, the split solve's set-up, colouring, SM's serial parts, the residual, the
# overflow colour) is serial. The bound printed is T / (S + W / N). On one thread the row packing and the
# bridge's pair tests run their serial loops, not their tasks (packTask, testPairs 0): bench/stages.sh counts
# them (about 2.0M and 2.1M instructions a step on the pile). Steps FROM..TO (default 301..450: the
# pile's heap is one partition from about step 120), as the difference of two runs.
#
#   bash bench/split_share.sh [SCENE] [FROM] [TO] [THREADS]      # pile 301 450 2
#
# KARMA_SPLIT_ROWS (default 2000) and KARMA_VARIANT (default nosleep) from the environment; BIN (default
# build/bench/bench/karma_scenes, built if missing).
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE=${1:-pile}
FROM=${2:-301}
TO=${3:-450}
THREADS=${4:-2}
export KARMA_SPLIT_ROWS=${KARMA_SPLIT_ROWS:-2000}
KARMA_VARIANT=${KARMA_VARIANT:-nosleep}
BIN=${BIN:-build/bench/bench/karma_scenes}
if [ ! -x "$BIN" ]; then
    cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
          -DKARMA_BUILD_TOOLS=OFF >/dev/null
    cmake --build build/bench --target karma_scenes >/dev/null
fi
command -v valgrind >/dev/null || { echo "split_share.sh: needs valgrind" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

TASKS="predictTask packTask solveTask integrateTask unpackTask testPairs KeaSweepChunks KeaScatterChunks \
KeaCgStartChunks KeaCgProductChunks KeaCgUpdateChunks KeaTrialChunks KeaSetUpRowChunks KeaColourAndWarmStartChunks \
KeaFactorBlockChunks KeaScatterPackChunks KeaResidualRowChunks KeaColourPacksAndListFreeItems KeaBodyVelocityRanges KeaPacksSetChunks KeaRowsCheckChunks"
# serial parts printed for reference (not counted as in tasks): the packs' scatter of an unsplit solve (a
# split solve scatters its packs colour by colour: KeaScatterPackChunks, in tasks)
SERIAL="KeaPacksScatter"
run() { # steps out
    valgrind --tool=callgrind --callgrind-out-file="$2" --toggle-collect=karma_step "$BIN" \
        --variants="$KARMA_VARIANT" --scenes="$SCENE" --steps="$1" --threads=1 >/dev/null 2>&1
}
# inclusive instructions of each function named in $TASKS, and the total (first line), from output $1
costs() {
    callgrind_annotate --inclusive=yes --threshold=100 "$1" 2>/dev/null | awk -v list="$TASKS $SERIAL" '
        BEGIN { n = split(list, f, " ") }
        /PROGRAM TOTALS/ { gsub(",", "", $1); total = $1 }
        { for (i = 1; i <= n; i++) if (!(f[i] in v) && $0 ~ (":" f[i] "( |$)")) { x = $1; gsub(",", "", x); v[f[i]] = x } }
        END { print "TOTAL", total; for (i = 1; i <= n; i++) print f[i], (f[i] in v) ? v[f[i]] : 0 }'
}
run $((FROM - 1)) "$work/a.out"
run "$TO" "$work/b.out"
costs "$work/a.out" >"$work/a.txt"
costs "$work/b.out" >"$work/b.txt"
join "$work/a.txt" "$work/b.txt" | awk -v steps=$((TO - FROM + 1)) -v n="$THREADS" -v scene="$SCENE" -v serial="$SERIAL" '
    BEGIN { ns = split(serial, sf, " "); for (i = 1; i <= ns; i++) isSerial[sf[i]] = 1 }
    { d[$1] = ($3 - $2) / steps
      if ($1 in isSerial) { sline = sline sprintf(" %s %.0f", $1, d[$1]) }
      else if ($1 != "TOTAL") { w += d[$1]; line = line sprintf(" %s %.0f", $1, d[$1]) } }
    END {
        t = d["TOTAL"]
        printf "%s, steps in window: %.0f instructions a step, %.0f in tasks (%.1f %%), bound at %d threads %.2fx\n",
               scene, t, w, 100 * w / t, n, t / (t - w + w / n)
        print "  by task per step:" line
        print "  serial, per step:" sline
    }'
