# Karma: a thin wrapper around CMake for the README's commands.
#
#   make demo      build, then run the Topple scene headless (karma run topple)
#   make test      build and test float (-O2, checks on), double, ASan + UBSan, the thread tests under
#                  ThreadSanitizer and the coverage floor of the Kea solver; prints "N passed, N failed"
#   make coverage  only the coverage configuration: gcov build, the solver's tests, gcovr fails below the
#                  Kea line-coverage floor (tests/run_configs.sh, docs/kea.md)
#   make build     build the float configuration (build/float)
#   make install   install it (PREFIX=/usr/local by default) and run ldconfig when that is needed
#   make docs      the API reference from the headers (Doxygen): build/docs/html/index.html, and the
#                  check that every public function has its comment
#   make deps      install missing Debian packages (as root), or print the apt-get line
#   make bench     build Release with -DKARMA_BUILD_BENCH=ON (build/bench) and run the benchmarks:
#                  dynamics on hand-made contacts, the collision space and the pair tests (bench/mcd),
#                  then the scenes against ODE and Bullet (bench/run.sh, which writes bench/RESULTS.md;
#                  installs libode-dev and libbullet-dev as root)
#   make bench-scenes  only the scenes against ODE and Bullet
#   make soak      build, then run the soak (tests/soak/soak.c: random creation and destruction through
#                  MstUniverse, checked for messages, memory, speed and determinism) for SOAK_SECONDS
#                  (default 300); make test runs a short one (soak_short)
#   make fuzz      build the libFuzzer harnesses of tests/fuzz with clang, ASan and UBSan (build/fuzz) and run
#                  each for FUZZ_SECONDS (default 60) from its seed corpus; fails on the first finding, whose
#                  input is left in build/fuzz/artifacts/<harness>/ (commit it to tests/fuzz/crashes/<harness>/)
#   make clean     remove build/

BUILD   ?= build/float
SOAK_SECONDS ?= 300
PREFIX  ?= /usr/local
JOBS    ?= 2
FUZZ_SECONDS ?= 60
FUZZERS := fuzz_pairs fuzz_lineseg fuzz_space fuzz_api
# The viewer (viewer/, karma render/view): GLFW, libepoxy, stb, the DejaVu font, and Mesa's EGL and
# software renderer for pictures without a display, Xvfb for the window test, ffmpeg for videos
# (`karma render --mp4`) (all run in make test).
VIEWER_PACKAGES := libglfw3-dev libepoxy-dev libstb-dev fonts-dejavu-core libegl1 libegl-mesa0 libgl1-mesa-dri \
                   xvfb xauth ffmpeg
DEBIAN_PACKAGES := cmake make gcc g++ libcmocka-dev pkg-config gcovr gnuplot-nox doxygen clang libclang-rt-14-dev universal-ctags \
                   $(VIEWER_PACKAGES)

.PHONY: all deps build test coverage demo install docs bench bench-scenes soak fuzz clean

all: build

# Packages are checked with dpkg-query; on a system without dpkg the check is skipped.
deps:
	@if command -v dpkg-query >/dev/null 2>&1; then \
	  missing=""; \
	  for p in $(DEBIAN_PACKAGES); do \
	    dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed$$' || missing="$$missing $$p"; \
	  done; \
	  if [ -n "$$missing" ]; then \
	    if [ "$$(id -u)" = 0 ]; then \
	      echo "installing:$$missing"; \
	      export DEBIAN_FRONTEND=noninteractive; \
	      apt-get -o DPkg::Lock::Timeout=600 update && \
	      apt-get -o DPkg::Lock::Timeout=600 install -y --no-install-recommends$$missing || exit 1; \
	    else \
	      echo "Karma needs these Debian packages:$$missing"; \
	      echo "install them with:"; \
	      echo "  sudo apt-get -o DPkg::Lock::Timeout=600 install -y$$missing"; \
	      exit 1; \
	    fi; \
	  fi; \
	fi

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DKARMA_CHECKS=ON
	cmake --build $(BUILD) -j $(JOBS)

test: deps
	@JOBS=$(JOBS) bash tests/run_configs.sh float double asan tsan coverage

coverage: deps
	@JOBS=$(JOBS) bash tests/run_configs.sh coverage

demo: build
	$(BUILD)/tools/karma run topple

# After installing, tools/install_ldconfig.sh runs ldconfig when root and the library's directory is one
# the loader searches (the default prefix on Debian), else prints the line to use (`sudo ldconfig`, or an
# rpath for a custom prefix). A staged install (DESTDIR=...) is left alone.
install: build
	DESTDIR="$(DESTDIR)" cmake --install $(BUILD) --prefix $(PREFIX)
	@DESTDIR="$(DESTDIR)" sh tools/install_ldconfig.sh \
	  "$(PREFIX)/$$(sed -n 's/^CMAKE_INSTALL_LIBDIR:PATH=//p' $(BUILD)/CMakeCache.txt)"

docs: deps
	doxygen docs/Doxyfile
	bash tests/scripts/check_api_comments.sh .
	@echo "API reference: build/docs/html/index.html (the user guide is its main page)"

# BENCH_ARGS is passed to the runner, e.g. make bench BENCH_ARGS="--scenes=chain --steps=100".
bench: deps
	cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DKARMA_BUILD_BENCH=ON -DKARMA_BUILD_TESTS=OFF -DKARMA_BUILD_TOOLS=OFF
	cmake --build build/bench -j $(JOBS) --target karma_bench_mdt mcd_space_bench mcd_nearfield_bench
	build/bench/bench/mdt/karma_bench_mdt $(BENCH_ARGS)
	build/bench/bench/mcd/mcd_space_bench
	build/bench/bench/mcd/mcd_nearfield_bench
	JOBS=$(JOBS) bash bench/run.sh

# New inputs go to build/fuzz/corpus/<harness> (the seed corpus in tests/fuzz/corpus is only read).
fuzz: deps
	cmake -S . -B build/fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKARMA_FUZZ=ON \
	  -DKARMA_BUILD_TESTS=OFF -DKARMA_BUILD_TOOLS=OFF
	cmake --build build/fuzz -j $(JOBS) --target $(FUZZERS)
	@for f in $(FUZZERS); do \
	  mkdir -p build/fuzz/corpus/$$f build/fuzz/artifacts/$$f || exit 1; \
	  echo "make fuzz: $$f for $(FUZZ_SECONDS) s"; \
	  build/fuzz/fuzz/$$f -max_total_time=$(FUZZ_SECONDS) -timeout=20 -print_final_stats=1 \
	    -artifact_prefix=build/fuzz/artifacts/$$f/ build/fuzz/corpus/$$f tests/fuzz/corpus/$$f \
	    > build/fuzz/$$f.log 2>&1 || { tail -n 40 build/fuzz/$$f.log; echo "make fuzz: $$f found a crash"; exit 1; }; \
	  grep -E '^stat::number_of_executed_units' build/fuzz/$$f.log; \
	done

clean:
	rm -rf build

.PHONY: soak
soak: build
	SOAK_SECONDS=$(SOAK_SECONDS) $(BUILD)/tests/karma_soak

# Scene benchmarks (issue 5): builds build/bench, runs Karma (when bench/karma/karma_scenes.c exists),
# ODE and Bullet on every scene and writes bench/RESULTS.md. Installs libode-dev and libbullet-dev
# when run as root. Not part of `make test`.
bench-scenes: deps
	JOBS=$(JOBS) bash bench/run.sh
