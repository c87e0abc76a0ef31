#!/usr/bin/env bash
# run_configs.sh -- build and test Karma in several configurations; `make test` calls it.
#
#   tests/run_configs.sh [CONFIG...]        CONFIG: float | double | asan | tsan | coverage (default: all)
#
#   float   build/float   Release (-O3) with KARMA_CHECKS=ON: argument checks on in an optimised build
#   double  build/double  Release, KARMA_DOUBLE=ON (MeReal = double)
#   asan    build/asan    Debug, KARMA_SANITIZE=ON (AddressSanitizer + UBSan, no recovery)
#   tsan    build/tsan    Debug, KARMA_TSAN=ON (ThreadSanitizer): only the library and the tests of
#                         threads (tests/threads: universes on threads, the step on a thread pool,
#                         the fallback counter on a pool; test_kea_split and determinism_split on
#                         2 threads: one partition split),
#                         to keep its time small
#   coverage build/coverage Debug, KARMA_COVERAGE=ON (gcov): the solver's tests (kea, bcl, mdt,
#                         analytic, determinism), then gcovr fails it when line coverage of the Kea
#                         sources (src/mdt/kea/) is below KEA_COVERAGE_FLOOR (docs/kea.md)
#
# Every configuration compiles with -std=c11 -Wall -Wextra -Werror -pedantic (and more; see
# cmake/KarmaFlags.cmake) and runs the whole CTest suite. A configuration that fails to configure or
# build counts as one failed test. The last line is the summary CI reads: "N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.."

JOBS=${JOBS:-2}
# The floor under Kea's line coverage, percent: raise it when tests are added, never lower it to pass.
KEA_COVERAGE_FLOOR=${KEA_COVERAGE_FLOOR:-92}
configs=("$@")
[ ${#configs[@]} -eq 0 ] && configs=(float double asan tsan coverage)

total_passed=0
total_failed=0
summary=()
start_all=$(date +%s)

for config in "${configs[@]}"; do
    case $config in
        float)  options=(-DCMAKE_BUILD_TYPE=Release -DKARMA_CHECKS=ON -DKARMA_DOUBLE=OFF -DKARMA_SANITIZE=OFF) ;;
        double) options=(-DCMAKE_BUILD_TYPE=Release -DKARMA_DOUBLE=ON -DKARMA_SANITIZE=OFF) ;;
        asan)   options=(-DCMAKE_BUILD_TYPE=Debug -DKARMA_SANITIZE=ON -DKARMA_DOUBLE=OFF) ;;
        tsan)   options=(-DCMAKE_BUILD_TYPE=Debug -DKARMA_TSAN=ON -DKARMA_SANITIZE=OFF -DKARMA_DOUBLE=OFF
                         -DKARMA_BUILD_TOOLS=OFF) ;;
        coverage) options=(-DCMAKE_BUILD_TYPE=Debug -DKARMA_COVERAGE=ON -DKARMA_SANITIZE=OFF -DKARMA_DOUBLE=OFF
                           -DKARMA_BUILD_TOOLS=OFF) ;;
        *) echo "run_configs.sh: unknown configuration '$config' (float, double, asan, tsan or coverage)" >&2
           exit 2 ;;
    esac
    # The tsan configuration builds and runs only the thread tests; the others everything.
    targets=()
    select=()
    if [ "$config" = tsan ]; then
        targets=(--target test_threads test_threaded_step test_threaded_fallbacks test_thread_pool test_kea_split test_determinism_split_threads2)
        select=(-R '^test_thread(s|ed_step|ed_fallbacks|_pool)$|^test_kea_split$|^test_determinism_split_threads2$')
    elif [ "$config" = coverage ]; then
        select=(-R '^test_(kea|determinism|analytic)|^test_(carwheel|chain|constraint_common|contact|hinge|joint|pendulum|prismatic|world_body|main_loop|matrix_capping|auto_disable|sim_check|stacking)')
    fi
    dir=build/$config
    start=$(date +%s)
    echo "==== $config: configure and build in $dir"
    mkdir -p "$dir"
    if ! cmake -S . -B "$dir" "${options[@]}" >"$dir/configure.log" 2>&1; then
        cat "$dir/configure.log"
        echo "==== $config: CONFIGURE FAILED"
        total_failed=$((total_failed + 1))
        summary+=("$config: configure failed")
        continue
    fi
    if ! cmake --build "$dir" -j "$JOBS" "${targets[@]}"; then
        echo "==== $config: BUILD FAILED"
        total_failed=$((total_failed + 1))
        summary+=("$config: build failed")
        continue
    fi
    echo "==== $config: test"
    log=$dir/ctest.log
    [ "$config" = coverage ] && find "$dir" -name '*.gcda' -delete  # counts of this run only
    ctest --test-dir "$dir" --output-on-failure -j "$JOBS" "${select[@]}" 2>&1 | tee "$log"
    line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1)
    if [ -z "$line" ]; then
        echo "==== $config: ctest produced no result"
        total_failed=$((total_failed + 1))
        summary+=("$config: no test result")
        continue
    fi
    failed=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
    count=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")
    failures=""
    if [ "$failed" -gt 0 ]; then
        # Name the failures where CI's tail shows them, and run each again once, alone: the physics is
        # deterministic, so a test that fails twice is a failure; one that passes alone depended on
        # the machine's load (a timing bound) and is named as such, counted as passed.
        names=$(sed -n '/The following tests FAILED:/,$p' "$log" | sed -nE 's/^[[:space:]]*[0-9]+ - ([^ ]+) .*/\1/p')
        again=()
        for name in $names; do
            echo "==== $config: $name failed; running it again alone"
            if ctest --test-dir "$dir" --output-on-failure -R "^${name}\$"; then
                failed=$((failed - 1))
                again+=("$name")
            else
                failures+=" $name"
            fi
        done
        [ ${#again[@]} -gt 0 ] && summary+=("$config: passed when run again alone (load-dependent): ${again[*]}")
    fi
    if [ "$config" = coverage ]; then
        # Counts from the tests just run only: gcovr merges every object file compiled from a Kea source.
        count=$((count + 1))
        if ! gcovr --root . --filter 'src/mdt/kea/' --fail-under-line "$KEA_COVERAGE_FLOOR" "$dir" \
                 >"$dir/coverage.txt" 2>&1; then
            failed=$((failed + 1))
            echo "==== coverage: Kea line coverage below ${KEA_COVERAGE_FLOOR}% (or gcovr failed)"
        fi
        cat "$dir/coverage.txt"
    fi
    passed=$((count - failed))
    total_passed=$((total_passed + passed))
    total_failed=$((total_failed + failed))
    summary+=("$config: $passed passed, $failed failed ($(( $(date +%s) - start )) s)${failures:+; failed:$failures}")
done

echo
echo "==== summary ($(( $(date +%s) - start_all )) s)"
for s in "${summary[@]}"; do echo "  $s"; done
echo "$total_passed passed, $total_failed failed"
[ "$total_failed" -eq 0 ]
