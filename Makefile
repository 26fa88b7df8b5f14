# The two commands of the README, and a few more. Each does all set-up it needs on a fresh
# Debian machine (scripts/setup.sh installs missing packages with apt-get).
MAKEFLAGS += --no-print-directory
BUILD ?= build
JOBS ?= $(shell nproc)
SITUATION ?= models/situations/near_goal_corner.json
STRATEGY ?= optimal_all

.PHONY: setup build test demo bench sanitize clean

setup:
	@bash scripts/setup.sh

build: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# The test command (CI runs exactly this through .ci/run).
test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The main job on the shipped defaults: a decision on a shipped situation, printed and drawn.
demo: build
	@mkdir -p out
	@$(BUILD)/app/foresight decide --situation $(SITUATION) --strategy $(STRATEGY) --svg out/decision.svg
	@echo
	@echo "drawing: out/decision.svg"

bench: build
	@$(BUILD)/bench/planner_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

# AddressSanitizer + UndefinedBehaviorSanitizer build of everything, then the tests.
sanitize: setup
	@cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DFORESIGHT_SANITIZE=ON -DFORESIGHT_BUILD_BENCH=OFF >/dev/null
	@cmake --build build-asan -j $(JOBS)
	@ctest --test-dir build-asan --output-on-failure -j $(JOBS)

clean:
	@rm -rf $(BUILD) build-asan out
