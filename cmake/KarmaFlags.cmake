# Compiler flags shared by every Karma target.
# Determinism: no fast-math, and no fused multiply-add contraction, so -O0 and -O2 agree bit for bit.
set(KARMA_C_FLAGS -ffp-contract=off -fno-fast-math)
set(KARMA_WARNINGS -Wall -Wextra -pedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes
                   -Wdouble-promotion -Wvla -Wno-unused-parameter)
if(KARMA_WERROR)
  list(APPEND KARMA_WARNINGS -Werror)
endif()

if(KARMA_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=all)
endif()

function(karma_apply_warnings target)
  target_compile_options(${target} PRIVATE ${KARMA_C_FLAGS} ${KARMA_WARNINGS})
endfunction()

# ThreadSanitizer (tests/run_configs.sh tsan): exclusive with KARMA_SANITIZE.
option(KARMA_TSAN "Build with ThreadSanitizer" OFF)
if(KARMA_TSAN)
  if(KARMA_SANITIZE)
    message(FATAL_ERROR "KARMA_TSAN and KARMA_SANITIZE cannot be combined")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()

# Line coverage (tests/run_configs.sh coverage, `make coverage`): gcc's --coverage on every target;
# tests/scripts/kea_coverage.sh reads the counts with gcovr and enforces the Kea floor.
option(KARMA_COVERAGE "Build with gcov instrumentation (--coverage)" OFF)
if(KARMA_COVERAGE)
  if(KARMA_SANITIZE OR KARMA_TSAN)
    message(FATAL_ERROR "KARMA_COVERAGE cannot be combined with a sanitizer")
  endif()
  # atomic counters: the threaded tests step partitions on several threads, and plain counters
  # updated by two threads at once come out negative, which gcovr refuses
  add_compile_options(--coverage -fprofile-update=atomic)
  add_link_options(--coverage -fprofile-update=atomic)
endif()
