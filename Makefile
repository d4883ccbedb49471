# vantage — one-command set-up. `make demo` and `make test` work on a fresh Debian 12 machine:
# they install the Debian packages, configure CMake in build/ (RelWithDebInfo), build, then run.

BUILD_DIR ?= build
SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= build-fuzz
INSTALL_DIR ?= $(CURDIR)/build-install
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
BUILD_TYPE ?= RelWithDebInfo
FUZZ_SECONDS ?= 60
FORMATS_FUZZ_SECONDS ?= 20
# Sanitizer and fuzzer builds: -O1 with line tables only. They compile about 2.3x faster than
# -O2 -g (analysis/src/perspective_start.cc under ASan+UBSan: 77 s against 177 s) and their
# reports still name file and line.
INSTRUMENTED_FLAGS ?= -O1 -g1 -DNDEBUG

.PHONY: all deps configure build demo test bench test-sanitize test-consumer fuzz format clean

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD_DIR)/CMakeCache.txt:
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

configure: deps $(BUILD_DIR)/CMakeCache.txt

build: configure
	cmake --build $(BUILD_DIR) -j $(JOBS)

demo: build
	$(BUILD_DIR)/cli/vantage analyze examples/layouts/satellite.json

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# The Python module alone (build/python/vantage; PYTHONPATH=build/python python3 -c "import vantage").
.PHONY: python
python: configure
	cmake --build $(BUILD_DIR) -j $(JOBS) --target vantage_python

bench: build
	$(BUILD_DIR)/bench/vantage_bench --benchmark_min_time=0.2

# The whole test suite once more under AddressSanitizer + UndefinedBehaviorSanitizer.
# print_suppressions=0: LeakSanitizer would otherwise print its table of suppressed leaks to
# stderr at exit, and the CLI tests require an empty stderr from a successful run.
test-sanitize: deps
	cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVANTAGE_SANITIZE=ON \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DVANTAGE_BUILD_BENCH=OFF -DVANTAGE_BUILD_EXAMPLES=OFF -DVANTAGE_BUILD_VIEWER=OFF
	cmake --build $(SANITIZE_DIR) -j $(JOBS)
	cd $(SANITIZE_DIR) && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS)

# Installs the library and builds tests/consumer against it with find_package(vantage).
test-consumer: build
	rm -rf $(INSTALL_DIR) $(BUILD_DIR)/consumer
	cmake --install $(BUILD_DIR) --prefix $(INSTALL_DIR)
	cmake -S tests/consumer -B $(BUILD_DIR)/consumer -DCMAKE_PREFIX_PATH=$(INSTALL_DIR)
	cmake --build $(BUILD_DIR)/consumer -j $(JOBS)
	$(BUILD_DIR)/consumer/vantage_consumer

# A short libFuzzer run of the layout parser on the seed corpus in examples/layouts.
fuzz: deps
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$(INSTRUMENTED_FLAGS)" \
	  -DVANTAGE_FUZZ=ON -DVANTAGE_BUILD_TESTS=OFF -DVANTAGE_BUILD_BENCH=OFF \
	  -DVANTAGE_BUILD_EXAMPLES=OFF -DVANTAGE_BUILD_VIEWER=OFF
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target vantage_fuzz_layout
	rm -rf $(FUZZ_DIR)/corpus && mkdir -p $(FUZZ_DIR)/corpus
	$(FUZZ_DIR)/fuzz/vantage_fuzz_layout -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	  $(FUZZ_DIR)/corpus examples/layouts
	cmake --build $(FUZZ_DIR) -j $(JOBS) --target vantage_fuzz_layout_formats
	rm -rf $(FUZZ_DIR)/corpus-formats && mkdir -p $(FUZZ_DIR)/corpus-formats
	$(FUZZ_DIR)/fuzz/vantage_fuzz_layout_formats -max_total_time=$(FORMATS_FUZZ_SECONDS) \
	  -print_final_stats=1 $(FUZZ_DIR)/corpus-formats examples/layouts

format:
	find analysis sdp design cli io viewer examples tests bench fuzz python \
	  \( -name '*.h' -o -name '*.cc' \) 2>/dev/null | xargs clang-format -i

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) $(FUZZ_DIR) $(INSTALL_DIR)

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
# markers added greedily and by the direct optimiser, feeds the design figure), the figures of the
# seed papers' experiments (each experiment run with its default trials and seed 1 into
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
	$(BUILD_DIR)/cli/vantage design examples/layouts/satellite.json --add 2 --json \
	  > $(BUILD_DIR)/satellite_design.json
	$(BUILD_DIR)/cli/vantage plot examples/layouts/satellite.json --out $(FIGURES_DIR) \
	  --design $(BUILD_DIR)/satellite_design.json
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
