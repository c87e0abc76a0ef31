#!/usr/bin/env bash
# run.sh -- build the scene benchmarks and run every available engine on every scene (issue 5), then
# write bench/RESULTS.md (tables: scene x engine) and bench/scene_results.csv (the raw lines).
#
#   bash bench/run.sh
#   BENCH_ARGS="--scenes=column,chain --steps=120" RESULTS=/tmp/r.md bash bench/run.sh   # a partial run
#
# Only the block between the scene-bench markers of RESULTS is rewritten; the rest of the file (other
# benchmarks' sections) is kept.
#
# Engines: karma_scenes (Karma; built when bench/karma/karma_scenes.c exists), ode_peer (ODE 0.16,
# variants quickstep20 and step) and bullet_peer (Bullet 3.24, variants si10 and si10-nosleep); a
# peer whose Debian package is missing is installed when run as root, otherwise skipped with a message.
# Each program prints one CSV line per (variant, scene) (see bench/scenes/bench_harness.h).
#
# Rounds: the timing of a shared VM drifts by tens of per cent, sometimes 2x, for minutes at a time,
# so the whole set (every scene, every engine in turn) runs ROUNDS times (default 3), each round
# minutes after the last, and the tables keep, per engine, variant and scene, the run with the lowest
# median CPU time (the figures of the rounds are the same: every engine is deterministic). ODE's
# dWorldStep, whose runs mostly stop at the time budget, runs in the first round only.
#
# Scene sets: SET=standard (default: the scenes of issue 5) or SET=others (issue 17's scene set of
# others' making, bench/scenes/README.md), each with its own block of RESULTS and its own CSV
# (scene_results.csv, scene_results_others.csv).
#
# Environment: SET (standard), BUILD (build dir, default build/bench), JOBS (2), BUDGET (seconds of CPU time in timed
# steps after which a run stops, default 30), ROUNDS (3), BENCH_ARGS (options passed to every program), RESULTS (default
# bench/RESULTS.md; the hand-written block between the "notes" markers of the old file is kept) and
# CSV (default scene_results.csv beside RESULTS).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=${BUILD:-build/bench}
JOBS=${JOBS:-2}
BUDGET=${BUDGET:-30}
ROUNDS=${ROUNDS:-3}
BENCH_ARGS=${BENCH_ARGS:-}
RESULTS=${RESULTS:-bench/RESULTS.md}
SET=${SET:-standard}
case "$SET" in
standard) marker=scene-bench title="Scenes against ODE and Bullet"; csv_name=scene_results.csv ;;
others) marker=scene-bench-others title="Scene set of others' making (issue 17)"; csv_name=scene_results_others.csv ;;
*) echo "run.sh: SET must be standard or others" >&2; exit 2 ;;
esac
CSV=${CSV:-$(dirname "$RESULTS")/$csv_name}
start=$(date +%s)
load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')

# ---- 1. packages ------------------------------------------------------------------------------------
missing=""
if command -v dpkg-query >/dev/null 2>&1; then
    for p in cmake make gcc g++ pkg-config libode-dev libbullet-dev; do
        dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' || missing="$missing $p"
    done
fi
if [ -n "$missing" ]; then
    if [ "$(id -u)" = 0 ]; then
        echo "run.sh: installing$missing"
        export DEBIAN_FRONTEND=noninteractive
        apt-get -o DPkg::Lock::Timeout=600 update >/dev/null
        apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends $missing >/dev/null
    else
        echo "run.sh: missing Debian packages:$missing (sudo apt-get install -y$missing); their engines are skipped"
    fi
fi

# ---- 2. build ---------------------------------------------------------------------------------------
# The commit measured, read before this script writes its own outputs (which would make it "-dirty").
commit=$(git describe --always --dirty 2>/dev/null || echo "?")
mkdir -p "$BUILD"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF \
      -DKARMA_BUILD_TOOLS=OFF >"$BUILD/configure.log" 2>&1 || { cat "$BUILD/configure.log"; exit 1; }
programs=()
[ -f bench/karma/karma_scenes.c ] && programs+=(karma_scenes)
pkg-config --exists ode 2>/dev/null && programs+=(ode_peer)
pkg-config --exists bullet 2>/dev/null && programs+=(bullet_peer)
if [ ${#programs[@]} -eq 0 ]; then
    echo "run.sh: no engine to run" >&2
    exit 1
fi
cmake --build "$BUILD" -j "$JOBS" --target "${programs[@]}"

# ---- 3. run -----------------------------------------------------------------------------------------
bin=$BUILD/bench
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/settings"
for prog in "${programs[@]}"; do
    "$bin/$prog" --set="$SET" --list >>"$tmp/settings"
done
# Scene by scene, every engine in turn: the engines compared on a scene run minutes apart at most, so
# that the load of a shared machine, which drifts, weighs on them alike. A --scenes= option in
# BENCH_ARGS runs as given, in one pass per engine.
scene_args=("")
case " $BENCH_ARGS " in
*" --scenes="*) ;;
*) mapfile -t scene_args < <(sed -n 's/^scene \([^:]*\):.*/--scenes=\1/p' "$tmp/settings" | awk '!seen[$0]++') ;;
esac
header=--header
: >"$tmp/raw"
for ((round = 1; round <= ROUNDS; round++)); do
    for scene_arg in "${scene_args[@]}"; do
        for prog in "${programs[@]}"; do
            only=
            case "$prog $BENCH_ARGS" in
            *--variants=*) ;;
            ode_peer*) [ "$round" -gt 1 ] && only=--variants=quickstep20 ;; # dWorldStep: one round
            esac
            echo "==== $prog ${scene_arg#--scenes=} (round $round of $ROUNDS)"
            # shellcheck disable=SC2086 # BENCH_ARGS is a list of options; scene_arg and only may be empty
            "$bin/$prog" $header --budget="$BUDGET" $BENCH_ARGS $only $scene_arg >>"$tmp/raw"
            header=
        done
    done
done
# Per (engine, variant, scene), the round with the lowest median CPU time (column 9; a run stopped
# early has "nan" and loses to any complete one), in the order the lines first appeared.
awk -F, 'NR == 1 { print; next }
    { key = $1 "," $2 "," $3; c = ($9 == "nan" || $9 == "") ? 1e300 : $9 + 0
      if (!(key in best)) { order[++n] = key; best[key] = c; line[key] = $0 }
      else if (c < best[key]) { best[key] = c; line[key] = $0 } }
    END { for (i = 1; i <= n; i++) print line[order[i]] }' "$tmp/raw" >"$tmp/csv"
elapsed=$(($(date +%s) - start))
load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')

# ---- 4. RESULTS.md ----------------------------------------------------------------------------------
cpu=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || true)
mem=$(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo 2>/dev/null || true)
notes_tag=notes
[ "$SET" = standard ] || notes_tag=notes-$SET
notes=$(sed -n "/^<!-- $notes_tag -->\$/,/^<!-- \\/$notes_tag -->\$/p" "$RESULTS" 2>/dev/null || true)
[ -n "$notes" ] || notes=$'<!-- '"$notes_tag"$' -->\n<!-- /'"$notes_tag"$' -->'
cp "$tmp/csv" "$CSV"
{
    echo "<!-- $marker:begin: written by bench/run.sh, which replaces this block and keeps the rest of the file -->"
    echo "## $title (\`SET=$SET bench/run.sh\`)"
    echo
    echo "Written by \`bench/run.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC') in ${elapsed} s (commit ${commit})."
    echo "Scenes and figures: \`bench/scenes/README.md\`. Lines (the best round of each): \`$(basename "$CSV")\`."
    echo
    echo "Machine: $(nproc) cores, ${cpu:-unknown CPU}, ${mem:-? GiB}; $(uname -sr); load average $load_start at the"
    echo "start and $load_end at the end (the machine is shared: a load above $(nproc) slows every engine alike);"
    echo "$(gcc --version | head -1), Release (-O3), ODE $(pkg-config --modversion ode 2>/dev/null || echo -),"
    echo "Bullet $(pkg-config --modversion bullet 2>/dev/null || echo -). Time budget per run: ${BUDGET} s of CPU time in timed steps${BENCH_ARGS:+; options: \`$BENCH_ARGS\`}."
    echo "The whole set ran ${ROUNDS} times (rounds minutes apart, every engine in turn on each scene); each row is"
    echo "the round with the lowest median CPU time (ODE's dWorldStep: the first round only)."
    echo
    echo "$notes"
    echo
    echo "### Engines"
    echo
    sed -n 's/^variant \([^ ]*\) \([^:]*\): \(.*\)/- **\1 \2**: \3/p' "$tmp/settings"
    echo
    echo "### Scenes"
    echo
    sed -n 's/^scene \([^:]*\): \(.*\)/- **\1**: \2/p' "$tmp/settings" | awk '!seen[$0]++'
    echo
    awk -F, -f - "$tmp/csv" <<'AWK'
    function fmt_ms(v) { return v == "nan" || v == "" ? "-" : sprintf(v < 1 ? "%.3f" : v < 100 ? "%.2f" : "%.0f", v) }
    function fmt_q(name, v) {
        if (v == "") return "-"
        if (name == "escaped") return sprintf("%d escaped", v)
        if (v == "nan") return "NaN"
        return sprintf("%.3g m", v)
    }
    # the figure, and for scenes with joints the mean of each step's largest gap after it
    function fmt_fig(i) { return fmt_q(qn[i], qv[i]) (jm[i] != "" && jm[i] != "nan" ? sprintf(", mean %.3g m", jm[i]) : "") }
    function ratio(a, b) { return (a != "nan" && b != "" && b != "nan" && b + 0 > 0) ? sprintf("%.2f", a / b) : "-" }
    NR == 1 { next }
    {
        n++; eng[n] = $1; var[n] = $2; sc[n] = $3; steps[n] = $5; run[n] = $6
        med[n] = $7; mean[n] = $8; cpu[n] = $9; con[n] = $10; qn[n] = $11; qv[n] = $12; st[n] = $13; pen[n] = $14; jm[n] = $15; note[n] = $16
        p99c[n] = $18
        if (!(sc[n] in seen)) { seen[sc[n]] = 1; scenes[++ns] = sc[n] }
        id = $1 " " $2; if (!(id in vseen)) { vseen[id] = 1; variants[++nv] = id }
        complete = run[n] == steps[n] && med[n] != "nan"
        if ($1 != "karma" && complete) {
            if (!(sc[n] in fastest) || med[n] + 0 < fastest[sc[n]] + 0) { fastest[sc[n]] = med[n]; fastname[sc[n]] = id }
            if (!(sc[n] in fastcpu) || cpu[n] + 0 < fastcpu[sc[n]] + 0) fastcpu[sc[n]] = cpu[n]
        }
        key[sc[n], id] = n
        if ($1 == "karma") haskarma = 1
    }
    END {
        print "### Per scene"
        print ""
        print "ms/step is the median over the run of the step call alone (collision included), wall clock"
        print "(CLOCK_MONOTONIC); CPU is the median process CPU time of the same calls, which the load of a"
        print "shared machine inflates far less; the mean shows what sleeping bodies hide from the median."
        print "CPU p99 is the 99th percentile of the same CPU times, and in brackets its ratio to the median."
        print "\"× fastest\" divides by the fastest peer that completed the scene (wall, CPU). A run that stops"
        print "early (time budget, island too large) has no figure and no verdict."
        for (s = 1; s <= ns; s++) {
            name = scenes[s]
            print ""
            f = (name in fastest) ? fastest[name] : ""
            fc = (name in fastcpu) ? fastcpu[name] : ""
            print "#### " name (f != "" ? " (fastest peer: " fastname[name] ")" : "")
            print ""
            print "| engine | variant | steps run | ms/step | CPU ms/step | CPU p99 (× median) | mean ms/step | contacts/step | figure | standing | floor pen. | × fastest | note |"
            print "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
            for (v = 1; v <= nv; v++) {
                if (!((name, variants[v]) in key)) continue
                i = key[name, variants[v]]
                printf "| %s | %s | %d / %d | %s | %s | %s (%s) | %s | %.0f | %s | %s | %s | %s, %s | %s |\n", eng[i], var[i], run[i], steps[i],
                       fmt_ms(med[i]), fmt_ms(cpu[i]), fmt_ms(p99c[i]), ratio(p99c[i], cpu[i]), fmt_ms(mean[i]), con[i], fmt_fig(i), st[i],
                       pen[i] == "" ? "-" : sprintf("%.1f mm", pen[i] * 1000), ratio(med[i], f), ratio(cpu[i], fc), note[i]
            }
        }
        print ""
        print "### Summary: median ms/step, wall / CPU (figure, standing)"
        print ""
        line = "| scene |"; sep = "|---|"
        for (v = 1; v <= nv; v++) { line = line " " variants[v] " |"; sep = sep "---|" }
        print line; print sep
        for (s = 1; s <= ns; s++) {
            line = "| " scenes[s] " |"
            for (v = 1; v <= nv; v++) {
                if (!((scenes[s], variants[v]) in key)) { line = line " |"; continue }
                i = key[scenes[s], variants[v]]
                cell = (run[i] == steps[i]) ? fmt_ms(med[i]) " / " fmt_ms(cpu[i]) " (" fmt_fig(i) (st[i] == "-" ? "" : ", " (st[i] == "yes" ? "standing" : "fallen")) ")" \
                                            : "stopped at " run[i] "/" steps[i]
                line = line " " cell " |"
            }
            print line
        }
        print ""
        print "### Karma against each peer"
        print ""
        if (!haskarma) {
            print "Karma's column is not measured yet: its collision layer and bridge are still being written."
            print "It appears here when `bench/karma/karma_scenes.c` exists (a BenchEngine over MstUniverse,"
            print "see `bench/scenes/README.md`): CMake then builds `karma_scenes` and this runner runs it."
        } else {
            print "Karma's median ms/step divided by each peer's, wall (CPU); below 1: Karma is faster."
            print ""
            line = "| scene | karma variant |"; sep = "|---|---|"
            for (v = 1; v <= nv; v++) if (variants[v] !~ /^karma /) { line = line " ÷ " variants[v] " |"; sep = sep "---|" }
            print line; print sep
            for (s = 1; s <= ns; s++)
                for (k = 1; k <= nv; k++) {
                    if (variants[k] !~ /^karma / || !((scenes[s], variants[k]) in key)) continue
                    i = key[scenes[s], variants[k]]
                    line = "| " scenes[s] " | " var[i] " |"
                    for (v = 1; v <= nv; v++) {
                        if (variants[v] ~ /^karma /) continue
                        j = (scenes[s], variants[v]) in key ? key[scenes[s], variants[v]] : 0
                        line = line " " ((j && run[j] == steps[j]) ? ratio(med[i], med[j]) " (" ratio(cpu[i], cpu[j]) ")" : "-") " |"
                    }
                    print line
                }
        }
    }
AWK
    echo "<!-- $marker:end -->"
} >"$tmp/block.md"
# Replace our block in RESULTS (other benchmarks keep their sections of the file), or add it.
if [ -f "$RESULTS" ] && grep -q "^<!-- $marker:begin" "$RESULTS"; then
    awk -v block="$tmp/block.md" -v begin="^<!-- $marker:begin" -v end="^<!-- $marker:end -->" '
        $0 ~ begin { while ((getline line < block) > 0) print line; skip = 1; next }
        $0 ~ end { skip = 0; next }
        !skip { print }' "$RESULTS" >"$RESULTS.tmp"
elif [ -f "$RESULTS" ]; then
    { cat "$RESULTS"; echo; cat "$tmp/block.md"; } >"$RESULTS.tmp"
else
    { echo "# Benchmark results"; echo; cat "$tmp/block.md"; } >"$RESULTS.tmp"
fi
mv "$RESULTS.tmp" "$RESULTS"
echo "run.sh: wrote $RESULTS and $CSV in ${elapsed} s"
