# Entry points for a fresh Debian 12 machine. Each target installs the Debian packages it needs.
BUILD := build/release
JOBS ?= $(shell nproc)

.PHONY: deps build demo test sanitize fuzz bench clean

deps:
	@scripts/install-deps.sh

build: deps
	@cmake --preset release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

demo: build
	@scripts/run-demo.sh $(BUILD)/apps/ancfnet/ancfnet

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The unit tests built with AddressSanitizer and UndefinedBehaviorSanitizer (build/sanitize).
sanitize: deps
	@cmake --preset sanitize >/dev/null
	@cmake --build build/sanitize -j $(JOBS) --target ancfnet_unit_tests
	@ANCFNET_SOURCE_DIR=$(CURDIR) OMP_NUM_THREADS=1 build/sanitize/tests/ancfnet_unit_tests

# The scene loader fuzzed with libFuzzer (clang, ASan + UBSan) for FUZZ_SECONDS (default 600):
# scripts/run-fuzzer.sh; findings in build/fuzz/artifacts/.
fuzz:
	@scripts/install-deps.sh --fuzz
	@cmake --preset fuzz >/dev/null
	@cmake --build build/fuzz -j $(JOBS) --target ancfnet_scene_fuzzer
	@scripts/run-fuzzer.sh build/fuzz

bench: build
	@scripts/install-deps.sh --bench
	@bench/run_scenarios.sh $(BUILD)

clean:
	rm -rf build
