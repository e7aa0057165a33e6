# The two commands of the README:
#   make demo   installs missing Debian packages, builds the CLI (Release) into build/, runs the main job
#   make test   installs missing Debian packages, builds, runs the whole test suite through CTest
# Reliability (docs/reliability.md):
#   make sanitize  the whole test suite built by clang with ASan + UBSan (build-sanitize/)
#   make fuzz      every libFuzzer target for FUZZ_SECONDS each (the same build)
#   make soak      every experiment scene for SOAK_SECONDS simulated (default 600)
BUILD ?= build
JOBS ?= $(shell nproc)
OUT ?= out
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release -DASPERITY_WERROR=ON

SANITIZE_BUILD ?= build-sanitize
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= scene png obj generators asset cli state
SOAK_SECONDS ?= 600

.PHONY: all deps configure build demo node-tools test bench format clean sanitize-build sanitize fuzz soak

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

# The demo builds only the command-line tool it runs (the library, the OpenGL renderer of the
# report's frames), not the tests and benchmarks that `make build` and `make test` add.
demo: configure
	@cmake --build $(BUILD) -j$(JOBS) --target asperity_cli
	@scripts/demo.sh $(BUILD)/bin $(OUT)

# Test tools from the npm registry (obj2gltf); the suite then requires them instead of skipping.
node-tools:
	@scripts/install-node-tools.sh $(BUILD)/node-tools

test: build node-tools
	@cd $(BUILD) && ASPERITY_REQUIRE_NODE_TOOLS=1 ASPERITY_REQUIRE_OPENEXR=1 ctest --output-on-failure -j$(JOBS) --timeout 600

# One clang build with ASan + UBSan serves the test suite and the libFuzzer targets alike, so
# the library is compiled once for both. Sanitizer reports abort the test that made them;
# libraries' own leaks (Mesa, fontconfig, assimp) are suppressed by name (tests/sanitizer/).
# intercept_tls_get_addr=0: clang 14's runtime can mistake a dynamic TLS block (Mesa's driver
# has them) for an old glibc header and crash LeakSanitizer's tracer at exit ("Tracer caught
# signal 11", fixed in LLVM 17); the block is then not scanned, and only the driver owns one.
# (The Python module is left out: it would need the sanitizer runtime preloaded into the
# interpreter.) The chain bolas' outcome test (22 runs of 3 s, 5 minutes under the sanitizers)
# is left to `make test` (run under the sanitizers by hand when chain_bolas.cpp changes), and
# so is the whole report, which runs the chain bolas too. So are the fine chain's capstan
# thresholds (115 s and 59 s under the sanitizers): the same chain and joints run sanitized in
# the coarser ChainOnRod and Capstan tests.
SANITIZE_SKIP ?= ^(ChainBolas\.WrapsTheRoughRodSlipsOffTheSmoothOne|ReportCommand\.EveryExperimentReproducesWithItsFrames|ChainOnRod\.FineChainCapstanThresholdIsLnROverPi(WhenConverged|WithFourSubsteps))$$

sanitize-build: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang \
	  -DCMAKE_CXX_COMPILER=clang++ -DASPERITY_SANITIZE=address,undefined -DASPERITY_FUZZ=ON \
	  -DASPERITY_BUILD_BENCH=OFF -DASPERITY_WITH_PYTHON=OFF >/dev/null
	@cmake --build $(SANITIZE_BUILD) -j$(JOBS)

sanitize: sanitize-build
	@cd $(SANITIZE_BUILD) && \
	  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/sanitizer/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j$(JOBS) --timeout 1200 -E '$(SANITIZE_SKIP)'

fuzz: sanitize-build
	@tests/fuzz/run.sh $(SANITIZE_BUILD)/bin $(FUZZ_SECONDS) $(FUZZ_TARGETS)

soak: build
	@cd $(BUILD) && ASPERITY_SOAK_SECONDS=$(SOAK_SECONDS) ctest --output-on-failure -j$(JOBS) \
	  -R 'Soak\.' --timeout 0

bench: build
	@for b in $(BUILD)/bin/asperity_*_bench; do echo "== $$b"; $$b; done

format:
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	@rm -rf $(BUILD) $(OUT) $(SANITIZE_BUILD)
