# vantage — one-command set-up. `make demo` and `make test` work on a fresh Debian 12 machine:
# they install the Debian packages, configure CMake in build/ (RelWithDebInfo), build, then run.
# `make demo` installs and builds only what it runs (the `vantage` command, without figures);
# `make test` installs and builds everything.

BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= build-fuzz
NO_NLOPT_DIR ?= build-without-nlopt
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
BUILD_TYPE ?= RelWithDebInfo
FUZZ_SECONDS ?= 60
# UNITY=ON compiles the libraries and the vantage command of `make test`, `make test-sanitize`
# and `make fuzz` in unity batches: faster from scratch (.ci/run uses it; `make fuzz`'s build
# 120 s against 144 s), slower to rebuild after an edit (the default, OFF, is for working on the
# code).
UNITY ?= OFF
FORMATS_FUZZ_SECONDS ?= 20
# The RelWithDebInfo build of `make demo` and `make test`: -O2 with line tables only (-g1), so
# that backtraces and sanitizer-free crash reports still name file and line. Full debug
# information (-g) makes every file compile about 1.5x slower (five of the heaviest sources:
# 30.2 s against 20.3 s of CPU, docs/benchmarks.md); configure a build of your own with
# OPTIMISED_FLAGS="-O2 -g -DNDEBUG" to step through variables in a debugger.
OPTIMISED_FLAGS ?= -O2 -g1 -DNDEBUG
# Sanitizer and fuzzer builds: -O1 with line tables only. They compile about 2.3x faster than
# -O2 -g (analysis/src/perspective_start.cc under ASan+UBSan: 77 s against 177 s) and their
# reports still name file and line.
INSTRUMENTED_FLAGS ?= -O1 -g1 -DNDEBUG

# Everything: what `make test` builds (optional parts off only when their dependency is missing).
FULL_OPTIONS = -DVANTAGE_WITH_NLOPT=ON -DVANTAGE_WITH_PLOT=ON -DVANTAGE_BUILD_TESTS=ON \
  -DVANTAGE_BUILD_BENCH=ON -DVANTAGE_BUILD_EXAMPLES=ON -DVANTAGE_BUILD_VIEWER=ON \
  -DVANTAGE_BUILD_PYTHON=ON -DVANTAGE_UNITY_BUILD=$(UNITY)
# What `make demo` runs: the `vantage` command without figures (vantage::plot needs PLplot, which
# brings about 220 Debian packages), and no tests, benchmarks, examples, viewer or Python.
# Unity batches: the lean build from scratch takes 407 s of CPU instead of 803 s (docs/benchmarks.md).
LEAN_OPTIONS = -DVANTAGE_WITH_PLOT=OFF -DVANTAGE_BUILD_TESTS=OFF -DVANTAGE_BUILD_BENCH=OFF \
  -DVANTAGE_BUILD_EXAMPLES=OFF -DVANTAGE_BUILD_VIEWER=OFF -DVANTAGE_BUILD_PYTHON=OFF \
  -DVANTAGE_UNITY_BUILD=ON

.PHONY: all deps deps-demo configure build demo test bench test-sanitize test-consumer \
  test-without-nlopt fuzz format clean

all: build

deps:
	@bash scripts/install-deps.sh all

deps-demo:
	@bash scripts/install-deps.sh demo

# Re-runs CMake with everything on (cheap when nothing changed), so that a build directory that
# `make demo` configured gets the rest.
configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(FULL_OPTIONS) \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(OPTIMISED_FLAGS)" \
	  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(OPTIMISED_FLAGS)"

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

# Configures $(BUILD_DIR) lean only when it is not configured yet (after `make test` the demo
# uses the full build as it is), builds the `vantage` command alone and runs it.
demo: deps-demo
	@test -f $(BUILD_DIR)/CMakeCache.txt || \
	  cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE) $(LEAN_OPTIONS) \
	    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(OPTIMISED_FLAGS)" \
	    -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(OPTIMISED_FLAGS)"
	cmake --build $(BUILD_DIR) -j $(JOBS) --target vantage
	$(BUILD_DIR)/cli/vantage analyze examples/layouts/satellite.json

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The Python module alone (build/python/vantage; PYTHONPATH=build/python python3 -c "import vantage").
.PHONY: python
python: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target vantage_python

bench: build
	$(BUILD_DIR)/bench/vantage_bench --benchmark_min_time=0.2

# The whole test suite once more under AddressSanitizer + UndefinedBehaviorSanitizer, but for
# the two checks of packaging that `make test` runs and instrumentation adds nothing to: the
# public-header compile check (not built) and the find_package consumer (label consumer).
# print_suppressions=0: LeakSanitizer would otherwise print its table of suppressed leaks to
# stderr at exit, and the CLI tests require an empty stderr from a successful run.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVANTAGE_SANITIZE=ON \
	  -DVANTAGE_UNITY_BUILD=$(UNITY) \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DVANTAGE_BUILD_BENCH=OFF -DVANTAGE_BUILD_EXAMPLES=OFF -DVANTAGE_BUILD_VIEWER=OFF \
	  -DVANTAGE_BUILD_HEADER_CHECK=OFF
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS) -LE consumer

# The consumer test of `make test` alone (tests/consumer/run_consumer.cmake): installs the build
# into a scratch prefix, builds and runs a find_package(vantage) consumer of the core (with
# pkg-config disabled, so it cannot reach PLplot) and one of COMPONENTS plot.
test-consumer: build
	cd $(BUILD_DIR) && ctest --output-on-failure -L consumer

# CI's check of the configuration without NLopt (and without figures, as `make demo` builds it):
# the libraries with parts that need NLopt (analysis, sdp, design) and their suites, whose
# nlopt_build tests check that those parts say "built without NLopt". Compiled at -O1 without
# debug information, for time.
test-without-nlopt: deps
	cmake -S . -B $(NO_NLOPT_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVANTAGE_WITH_NLOPT=OFF \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" \
	  $(LEAN_OPTIONS) -DVANTAGE_BUILD_TESTS=ON
	cmake --build $(NO_NLOPT_DIR) -j $(JOBS) \
	  --target vantage_analysis_tests vantage_sdp_tests vantage_design_tests
	cd $(NO_NLOPT_DIR) && ctest --output-on-failure -j $(JOBS) -L '^(analysis|sdp|design)$$'

# A short libFuzzer run of the layout parser on the seed corpus in examples/layouts.
fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DVANTAGE_FUZZ=ON -DVANTAGE_UNITY_BUILD=$(UNITY) -DVANTAGE_BUILD_TESTS=OFF -DVANTAGE_BUILD_BENCH=OFF \
	  -DVANTAGE_BUILD_EXAMPLES=OFF -DVANTAGE_BUILD_VIEWER=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target vantage_fuzz_layout
	rm -rf $(FUZZ_DIR)/corpus && mkdir -p $(FUZZ_DIR)/corpus
	$(FUZZ_DIR)/fuzz/vantage_fuzz_layout -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	  $(FUZZ_DIR)/corpus examples/layouts
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target vantage_fuzz_layout_formats
	rm -rf $(FUZZ_DIR)/corpus-formats && mkdir -p $(FUZZ_DIR)/corpus-formats
	$(FUZZ_DIR)/fuzz/vantage_fuzz_layout_formats -max_total_time=$(FORMATS_FUZZ_SECONDS) \
	  -print_final_stats=1 $(FUZZ_DIR)/corpus-formats examples/layouts examples/tools

format:
	find analysis body sdp visibility report tracker camera design commands cli io plot simulate viewer \
	  examples tests bench fuzz python \
	  \( -name '*.h' -o -name '*.cc' \) 2>/dev/null | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR) $(NO_NLOPT_DIR)

# Optional: vantage's pose estimators against OpenCV's solvePnP (bench/peers). Installs
# libopencv-dev first (not part of `make deps`: `make test` and `make demo` never need OpenCV),
# re-configures so that CMake finds it, builds and prints the table of docs/benchmarks.md.
.PHONY: bench-peers
bench-peers: configure
	@if [ "$$(id -u)" -eq 0 ]; then apt-get install -y libopencv-dev; \
	  else sudo apt-get install -y libopencv-dev; fi
	cmake -S . -B $(BUILD_DIR)
	cmake --build $(BUILD_DIR) -j $(JOBS) --target vantage_pose_peers
	$(BUILD_DIR)/bench/peers/vantage_pose_peers --trials 500

# Every figure in docs/figures (PNG + the CSV of each; only the PNGs are kept in git), shown in
# README.md and docs/results.md: the five figures of the satellite example (a design run, two
# markers added greedily and by the direct optimiser, feeds the design figure), the TRE figures of
# the NDI-like tool (tre_tip_axis, tre_polar, tre_map; 0.2 s), the figures of the seed papers'
# experiments (each experiment run with its default trials and seed 1 into
# $(EXPERIMENTS_DIR)/NAME, drawn there by `vantage plot --experiment`, copied here as
# experiment_<figure>.png) and the viewer's screenshot (under xvfb-run). Not part of `make test`
# or `make demo`. Once built: 23 s on this shared 2-core machine, screenshot included. Every
# figure is deterministic except experiment_wu_points_time.png, whose times vary between runs.
FIGURES_DIR ?= docs/figures
EXPERIMENTS_DIR ?= $(BUILD_DIR)/experiments
# experiment NAME : the figures it draws (vantage plot --experiment NAME).
FIGURE_EXPERIMENTS = bound:bound mcinroy-orientation:mcinroy_orientation \
  mcinroy-pose:mcinroy_pose haralick-2d2d:haralick_2d2d_knee \
  wu-points:wu_points_accuracy,wu_points_time wu-snr:wu_snr_accuracy
.PHONY: figures
figures: build
	mkdir -p $(FIGURES_DIR)
	$(BUILD_DIR)/cli/vantage design examples/layouts/satellite.json --seen-whole --add 2 --json \
	  > $(BUILD_DIR)/satellite_design.json
	$(BUILD_DIR)/cli/vantage plot examples/layouts/satellite.json --seen-whole \
	  --out $(FIGURES_DIR) --design $(BUILD_DIR)/satellite_design.json
	rm -rf $(BUILD_DIR)/satellite_body && $(BUILD_DIR)/cli/vantage plot \
	  examples/layouts/satellite.json --out $(BUILD_DIR)/satellite_body --only viewpoint_map,visibility
	cp $(BUILD_DIR)/satellite_body/viewpoint_map.png $(FIGURES_DIR)/satellite_visibility.png
	cp $(BUILD_DIR)/satellite_body/visibility.png $(FIGURES_DIR)/satellite_visible_markers.png
	$(BUILD_DIR)/cli/vantage plot examples/tools/ndi_like.json --tre --target 0,0,-150 \
	  --fle-sigma 0.0995,0.2985 --out $(FIGURES_DIR) > /dev/null
	set -e; for entry in $(FIGURE_EXPERIMENTS); do \
	  name=$${entry%%:*}; dir=$(EXPERIMENTS_DIR)/$$name; \
	  rm -rf $$dir; \
	  $(BUILD_DIR)/cli/vantage experiment $$name --out $$dir --seed 1 --quiet; \
	  $(BUILD_DIR)/cli/vantage plot --experiment $$name --out $$dir > /dev/null; \
	  for figure in $$(echo $${entry#*:} | tr , ' '); do \
	    cp $$dir/$$figure.png $(FIGURES_DIR)/experiment_$$figure.png; \
	    cp $$dir/$$figure.csv $(FIGURES_DIR)/experiment_$$figure.csv; \
	  done; \
	done
	xvfb-run -a -s '-screen 0 1600x1200x24' $(BUILD_DIR)/viewer/vantage-viewer \
	  examples/layouts/satellite.json --screenshot $(FIGURES_DIR)/viewer.png --size 1400x900 \
	  --view iso --frames 3
	$(BUILD_DIR)/cli/vantage place examples/bodies/satellite.obj --markers 4 --candidates 200 \
	  --workspace 0,0,1,60 --cone-deg 80 --out $(BUILD_DIR)/satellite_top.json --overwrite --quiet
	xvfb-run -a -s '-screen 0 1600x1200x24' $(BUILD_DIR)/viewer/vantage-viewer \
	  $(BUILD_DIR)/satellite_top.json --place 8 --screenshot $(FIGURES_DIR)/viewer_place.png \
	  --size 1400x1200 --view top --frames 3
