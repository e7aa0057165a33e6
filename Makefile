# The two commands of the README:
#   make demo   installs missing Debian packages, builds (Release) into build/, runs the main job
#   make test   installs missing Debian packages, builds, runs the whole test suite through CTest
BUILD ?= build
JOBS ?= $(shell nproc)
OUT ?= out
CMAKE_FLAGS ?= -DCMAKE_BUILD_TYPE=Release -DASPERITY_WERROR=ON

.PHONY: all deps configure build demo test bench format clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

demo: build
	@scripts/demo.sh $(BUILD)/bin $(OUT)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j$(JOBS) --timeout 600

bench: build
	@for b in $(BUILD)/bin/asperity_*_bench; do echo "== $$b"; $$b; done

format:
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

clean:
	@rm -rf $(BUILD) $(OUT)
