#!/usr/bin/env bash
# instructions.sh -- instructions per step of every engine on one scene, over a range of steps,
# counted by valgrind (callgrind): the same figure on every run, where times on a shared VM drift by
# tens of per cent for minutes at a time. Instructions are not time (engines differ in how many they
# retire per cycle), but a change that lowers them, or a ratio that moves, is real.
#
#   bash bench/instructions.sh                  # pile, steps 301-600 (the regime of its median step)
#   bash bench/instructions.sh ragdolls 0 300   # ragdolls, the first 300 steps
#
# Each engine variant runs the scene twice, for FROM and for TO steps (FROM 0: once), and the
# difference divided by TO - FROM is its instructions per step in that range; collision, the step's
# every stage and the harness's own per-step work are counted, setup and teardown cancel out.
# Variants: Karma default and nosleep, Bullet si10 and si10-nosleep, ODE quickstep20 (whichever are
# built). Takes a few minutes for the pile (valgrind runs ~50x slower); two runs go at a time.
#
# Environment: BUILD (default build/bench, configured and built like bench/run.sh does), JOBS (2),
# COLLECT (all, the default: the whole program, setup cancelled by the FROM run; step: only the engines'
# step callbacks, karma_step, ode_step and bullet_step, with callgrind's --toggle-collect, so that
# FROM 0 needs one run and neither setup nor the harness's per-step reading is counted: half the
# valgrind time, for a loaded machine), VARIANTS (a space-separated subset of the variants above, e.g. "nosleep si10-nosleep quickstep20" for
# the awake comparison; default all).
set -euo pipefail
cd "$(dirname "$0")/.."

SCENE=${1:-pile}
FROM=${2:-300}
TO=${3:-600}
BUILD=${BUILD:-build/bench}
JOBS=${JOBS:-2}
if ! [[ "$FROM" =~ ^[0-9]+$ && "$TO" =~ ^[0-9]+$ ]] || [ "$TO" -le "$FROM" ]; then
    echo "usage: bash bench/instructions.sh [SCENE] [FROM] [TO]   (0 <= FROM < TO, in steps)" >&2
    exit 2
fi
command -v valgrind >/dev/null || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }

cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
      -DKARMA_BUILD_TOOLS=OFF >/dev/null
runs=()
[ -f bench/karma/karma_scenes.c ] && runs+=("karma_scenes default" "karma_scenes nosleep")
pkg-config --exists bullet 2>/dev/null && runs+=("bullet_peer si10" "bullet_peer si10-nosleep")
pkg-config --exists ode 2>/dev/null && runs+=("ode_peer quickstep20")
if [ -n "${VARIANTS:-}" ]; then
    kept=()
    for run in "${runs[@]}"; do
        case " $VARIANTS " in *" ${run#* } "*) kept+=("$run") ;; esac
    done
    runs=("${kept[@]}")
fi
targets=$(printf '%s\n' "${runs[@]}" | cut -d' ' -f1 | sort -u | tr '\n' ' ')
# shellcheck disable=SC2086 # a list of targets
cmake --build "$BUILD" -j "$JOBS" --target $targets >/dev/null
"$BUILD/bench/karma_scenes" --scenes="$SCENE" --steps=1 >/dev/null 2>&1 ||
    { echo "instructions.sh: unknown scene '$SCENE'" >&2; exit 2; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# One counted run: the total instructions of the program (valgrind's "Collected" line).
collect=()
[ "${COLLECT:-all}" = step ] &&
    collect=(--collect-atstart=no --toggle-collect=karma_step --toggle-collect=ode_step --toggle-collect='*bullet_step*')
count() { # program variant steps outfile
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "${collect[@]}" "$BUILD/bench/$1" --variants="$2" \
        --scenes="$SCENE" --steps="$3" --budget=1000000 2>&1 >/dev/null |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p' >"$4"
}
jobs_running=0
for run in "${runs[@]}"; do
    read -r prog variant <<<"$run"
    for steps in $FROM $TO; do
        [ "$steps" -eq 0 ] && { echo 0 >"$tmp/$variant.$steps"; continue; }
        count "$prog" "$variant" "$steps" "$tmp/$variant.$steps" &
        jobs_running=$((jobs_running + 1))
        if [ "$jobs_running" -ge "$JOBS" ]; then
            wait -n
            jobs_running=$((jobs_running - 1))
        fi
    done
done
wait

what=""
[ "${COLLECT:-all}" = step ] && what=", the step callbacks alone"
echo "Instructions per step, $SCENE, steps $((FROM + 1))-$TO (valgrind callgrind$what; $(git describe --always --dirty))"
echo
echo "| engine | variant | instructions per step | ÷ first row |"
echo "|---|---|---|---|"
first=
for run in "${runs[@]}"; do
    read -r prog variant <<<"$run"
    a=$(cat "$tmp/$variant.$FROM")
    b=$(cat "$tmp/$variant.$TO")
    if [ -z "$a" ] || [ -z "$b" ]; then
        echo "| ${prog%%_*} | $variant | (run failed) | - |"
        continue
    fi
    per=$(((b - a) / (TO - FROM)))
    [ -n "$first" ] || first=$per
    awk -v e="${prog%%_*}" -v v="$variant" -v p="$per" -v f="$first" \
        'BEGIN { printf "| %s | %s | %.2fM | %.2f |\n", e, v, p / 1e6, p / f }'
done
