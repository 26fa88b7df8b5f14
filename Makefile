# The two commands of the README, and a few more. Each does all set-up it needs on a fresh
# Debian machine (scripts/setup.sh installs missing packages with apt-get).
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc)
SITUATION ?= models/situations/near_goal_corner.json
STRATEGY ?= optimal_all
# The robot's base in `make main`'s physics (floating: the robot on its own feet, the ground truth
# and the physics files' default; fixed: the torso bolted to the world, the fast approximation at
# about a tenth of the cost, docs/PERFORMANCE.md).
BASE ?= floating

FUZZ_RUNS ?= 20000
FUZZ_TIMEOUT ?= 10

.PHONY: setup build test main demo deb experiments experiments-quick bench same-bytes sanitize fuzz clean

setup:
	@bash scripts/setup.sh

build: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The test command (CI runs it through .ci/run): the GoogleTest suite with the layering check,
# the installed package's consumer project, the Python module's pytest suite, sharded runs with
# GNU parallel and on a one-node Slurm cluster (issue 17),
# the physics checks of models/check_specs/default.json (JUnit XML in
# $(BUILD)/check-junit.xml) and the check of the shipped case base.
test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	@$(BUILD)/app/foresight check --junit $(BUILD)/check-junit.xml
	@$(BUILD)/app/foresight cbr check

# The main job on the shipped defaults: calibrate the NAO's kicks from physics, write the
# calibrated kick model, compare the coarse model (with that model) against physics on the
# quick situation set, and write both reports, with the robot standing on its own feet (about 6
# minutes after the build on 2 cores). `make main BASE=fixed` does it all on the fixed base, the
# fast approximation (about a minute).
main: build
	@mkdir -p out
	@$(BUILD)/app/foresight calibrate --robot nao --all --trials 1000 --base $(BASE) --out out/nao_calibrated.json --report out/calibration
	@echo
	@$(BUILD)/app/foresight fidelity --situations quick --kicks out/nao_calibrated.json --trials 30 --base $(BASE) --out out/fidelity
	@echo
	@echo "calibrated kick model: out/nao_calibrated.json"
	@echo "reports: out/calibration/calibration.html and out/fidelity/fidelity.html"

# The Debian package $(BUILD)/foresight_<version>_amd64.deb (issue 17), built for prefix /usr so
# that programs linked against its libraries find its data; install it with
# `apt-get install ./$(BUILD)/foresight_*_amd64.deb`.
deb: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)
	@cd $(BUILD) && cpack -G DEB

# A decision on a shipped situation, printed and drawn.
demo: build
	@mkdir -p out
	@$(BUILD)/app/foresight decide --situation $(SITUATION) --strategy $(STRATEGY) --svg out/decision.svg
	@echo
	@echo "drawing: out/decision.svg"

# The paper's two experiments on the shipped defaults (docs/EXPERIMENTS.md): decision stability
# on the full grid (about 8 min on 2 cores) and the four strategies from 10,000 starts (about
# 25 s); experiments-quick runs small versions in seconds.
experiments: build
	@mkdir -p out/experiments
	@$(BUILD)/app/foresight experiment stability --out out/experiments/stability
	@echo
	@$(BUILD)/app/foresight experiment strategies --out out/experiments/strategies

experiments-quick: build
	@mkdir -p out/experiments
	@$(BUILD)/app/foresight experiment stability --quick --out out/experiments/stability_quick
	@echo
	@$(BUILD)/app/foresight experiment strategies --starts 500 --out out/experiments/strategies_quick

bench: build
	@$(BUILD)/bench/planner_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

# Builds for every SIMD width (GCC default and silvermont: 2 lanes, haswell: 4, native: the
# widest) and with Clang must decide with the same bits (scripts/same_bytes.sh); CI runs it.
same-bytes: setup
	@bash scripts/same_bytes.sh $(BUILD)-march

# AddressSanitizer + UndefinedBehaviorSanitizer build of everything, then the tests and two real
# runs (a small fidelity report and the strategies experiment). The fidelity run (864 trials) is
# on the fixed base, at a tenth of a floating trial's cost: the floating base's code runs under
# the sanitizers in the suite's floating tests.
sanitize: setup
	@cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DFORESIGHT_SANITIZE=ON -DFORESIGHT_BUILD_BENCH=OFF -DFORESIGHT_BUILD_PYTHON=OFF >/dev/null
	@cmake --build build-asan -j $(JOBS)
	@LSAN_OPTIONS=suppressions=$(CURDIR)/scripts/lsan_suppressions.txt ctest --test-dir build-asan --output-on-failure -j $(JOBS)
	@build-asan/app/foresight fidelity --situations quick --trials 4 --converged 200 --base fixed --out build-asan/sanitize-fidelity >/dev/null
	@build-asan/app/foresight experiment strategies --starts 50 --out build-asan/sanitize-strategies >/dev/null
	@echo "sanitize: tests, fidelity --situations quick and experiment strategies ran clean"

# libFuzzer targets for every reader (fuzz/), built with clang, AddressSanitizer and UBSan, each
# run for FUZZ_RUNS inputs from the seed corpus in models/ with a fixed libFuzzer seed (so a run
# is reproducible), then on large inputs of several shapes; every input has FUZZ_TIMEOUT seconds
# (so a reader that is quadratic in its input fails); a finding fails and leaves its input in
# build-fuzz/findings/.
fuzz: setup
	@CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFORESIGHT_FUZZ=ON -DFORESIGHT_BUILD_TESTS=OFF -DFORESIGHT_BUILD_BENCH=OFF -DFORESIGHT_BUILD_PYTHON=OFF >/dev/null
	@cmake --build build-fuzz -j $(JOBS) --target fuzz_readers
	@FUZZ_TIMEOUT=$(FUZZ_TIMEOUT) bash scripts/run_fuzzers.sh build-fuzz $(FUZZ_RUNS)

clean:
	@rm -rf $(BUILD) $(BUILD)-march-silvermont $(BUILD)-march-native build-asan build-fuzz out
