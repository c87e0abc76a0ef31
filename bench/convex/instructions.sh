#!/bin/bash
# Issue 18 point 6: instructions per pair test and per step of the convex and terrain scenes, Karma
# Bullet and ODE, counted by callgrind over steps FROM+1 ... TO only (the client requests of
# convex_scenes.c switch the instrumentation on and off), then the top functions of each run.
# Usage: bash bench/convex/instructions.sh [FROM] [TO] [BUILD]   (default 300 310 build/bench)
set -e
FROM=${1:-300}
TO=${2:-310}
B=${3:-build/bench}/bench/convex
OUT=$(mktemp -d)
echo "| engine | scene | instructions per test or step |"
echo "|---|---|---|"
for e in karma bullet ode; do
  valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=$OUT/$e.pairs.out $B/convex_$e pairs >/dev/null 2>&1
  ir=$(awk '/^totals:/ {print $2}' $OUT/$e.pairs.out)
  echo "| $e | pairs | $((ir / 2048)) |"
  for s in pile mesh field; do
    valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=$OUT/$e.$s.out $B/convex_$e $s --steps=$TO --from=$FROM >/dev/null 2>&1
    ir=$(awk '/^totals:/ {print $2}' $OUT/$e.$s.out)
    echo "| $e | $s | $((ir / (TO - FROM))) |"
  done
done
for f in $OUT/*.out; do
  echo; echo "## $(basename $f .out): top functions (exclusive)"
  callgrind_annotate $f 2>/dev/null | sed -n '/^Ir/,$p' | sed -n 3,20p
done
echo; echo "callgrind files: $OUT"
