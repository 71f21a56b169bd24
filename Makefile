# The README's commands. Each one installs what is missing (scripts/setup.sh), then builds.
BUILD      ?= build
BUILD_ASAN ?= build-asan
JOBS       ?= $(shell nproc)
PARKLOC    := $(BUILD)/apps/parkloc/parkloc

.PHONY: setup configure build test test-asan demo bench format clean

setup:
	@scripts/setup.sh

configure: setup
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

test-asan: setup
	@cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" -DPARKLOC_SANITIZE=ON \
	  -DPARKLOC_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(BUILD_ASAN) -j $(JOBS)
	@cd $(BUILD_ASAN) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0 \
	  ctest --output-on-failure -j $(JOBS) -LE slow

demo: build
	@$(PARKLOC) demo

bench: build
	@for b in $(BUILD)/bench/bench_*; do [ -x "$$b" ] && "$$b" --benchmark_min_time=0.2 || exit 1; done

format:
	@find src apps tests bench -name '*.h' -o -name '*.cc' | xargs clang-format -i

clean:
	@rm -rf $(BUILD) $(BUILD_ASAN)

# Fuzzing (docs/RELIABILITY.md): libFuzzer targets for every parser of outside data, built
# with clang and ASan + UBSan in $(BUILD_FUZZ). `make fuzz` runs each target FUZZ_SECONDS
# (FUZZ_RUNS=N: N executions instead); `make fuzz-smoke` runs each for a few seconds (CI).
BUILD_FUZZ   ?= build-fuzz
FUZZ_SECONDS ?= 300
FUZZ_SMOKE_SECONDS ?= 8

.PHONY: fuzz-build fuzz fuzz-smoke

fuzz-build: setup
	@CC=clang CXX=clang++ cmake -S . -B $(BUILD_FUZZ) -DPARKLOC_FUZZ=ON -DPARKLOC_BUILD_TESTS=OFF \
	  -DPARKLOC_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g -O1" >/dev/null
	@cmake --build $(BUILD_FUZZ) -j $(JOBS) --target fuzz_targets

fuzz: fuzz-build
	@fuzz/run.sh $(BUILD_FUZZ) $(FUZZ_SECONDS)

fuzz-smoke: fuzz-build
	@fuzz/run.sh $(BUILD_FUZZ) $(FUZZ_SMOKE_SECONDS)
