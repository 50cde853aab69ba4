# nspd — the commands a newcomer types. Each target installs what it needs
# (scripts/deps.sh: Debian packages, as root) and builds with CMake.
#
#   make demo       set up, build, run the flagship case into out/
#   make test       set up, build, run the whole test suite (ctest), 7-10 min on 2 cores
#   make bench      benchmarks (never part of make test); results in bench/results/
#   make validate   full-resolution paper cases and their plots (long)
#   make format     clang-format every C file;  make tidy: clang-tidy
#   make fuzz       libFuzzer on the case, .vtr, expression, STL and .inp readers, FUZZ_SECONDS each (default 600)

BUILD      ?= build
BUILD_ASAN ?= build-asan
BUILD_FUZZ ?= build-fuzz
FUZZ_SECONDS ?= 600
JOBS       ?= $(shell nproc)
CMAKE_ARGS ?=
# Ninja (installed by scripts/deps.sh) packs the two cores better than
# make's recursive Makefiles: the release build in 59 s against 78 s
# (docs/PERFORMANCE.md, "make test on 2 cores"). A build directory keeps the generator
# it was configured with.
GENERATOR  ?= Ninja
NSPD        = $(BUILD)/nspd

.PHONY: all deps build test test-fast test-asan demo bench validate fuzz format format-check tidy clean

all: build

deps:
	@scripts/deps.sh build

$(BUILD)/CMakeCache.txt:
	@scripts/deps.sh build
	cmake -G "$(GENERATOR)" -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The whole suite: the release build's tests, then the unit tests again under
# AddressSanitizer + UBSan. Tests labelled "slow" belong to `make validate`;
# "release" tests compare bits the release build produces (tests/golden).
test: build test-asan
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE slow

test-fast: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -L unit

$(BUILD_ASAN)/CMakeCache.txt:
	@scripts/deps.sh build
	cmake -G "$(GENERATOR)" -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=Debug -DNSPD_SANITIZE=ON $(CMAKE_ARGS)

test-asan: deps $(BUILD_ASAN)/CMakeCache.txt
	cmake --build $(BUILD_ASAN) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	    ctest --test-dir $(BUILD_ASAN) --output-on-failure -j $(JOBS) -L "unit|cli" -LE release

demo: build
	scripts/demo.sh $(NSPD)

bench: build
	@scripts/deps.sh build bench
	bench/run_all.sh $(NSPD)

validate: build
	@scripts/deps.sh build validate
	scripts/validate.sh $(NSPD) $(BUILD)

# The fuzz harnesses (tests/fuzz/) built with clang, libFuzzer, ASan and
# UBSan in their own build directory, then run one after the other on one
# core; what they find lands in tests/fuzz/regressions/ (docs/RELIABILITY.md).
# Warnings are not errors here: clang warns where gcc, the compiler the
# build checks, does not.
$(BUILD_FUZZ)/CMakeCache.txt:
	@scripts/deps.sh build fuzz
	CC=clang cmake -G "$(GENERATOR)" -S . -B $(BUILD_FUZZ) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNSPD_SANITIZE=ON \
	    -DNSPD_FUZZ=ON -DNSPD_TESTS=OFF -DNSPD_WERROR=OFF $(CMAKE_ARGS)

fuzz: $(BUILD_FUZZ)/CMakeCache.txt
	cmake --build $(BUILD_FUZZ) -j $(JOBS) --target fuzz_case fuzz_vtk fuzz_sim fuzz_expr fuzz_stl fuzz_inp
	tests/fuzz/fuzz.sh $(BUILD_FUZZ) $(FUZZ_SECONDS)

format: $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) --target format

format-check: $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) --target format-check

tidy: $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) --target tidy

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD_FUZZ)
