# Two commands do everything on a fresh Debian 12 machine (as root):
#   make demo   installs what is missing, builds, renders every configuration into out/demo
#   make test   installs what is missing, builds, runs every test
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?= -DPENUMBRA_WERROR=ON
PENUMBRA = $(BUILD)/bin/penumbra

.PHONY: all deps configure build test demo bench sanitize clean

all: build

deps:
	@./scripts/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) --log-level=WARNING

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# The parity report of every configuration (out/demo/<configuration>/{pattern,lit,atlas,cascades}.png,
# atlas.exr, out/demo/index.html, parity.json), then the key-light scene through both backends.
demo: build
	@$(PENUMBRA) parity --scene test --out out/demo
	@$(PENUMBRA) render --backend vulkan,opengl --scene key-light --out out/demo/render/key-light.png \
		--atlas out/demo/render/key-light-atlas --debug cascades

bench: build
	@$(PENUMBRA) bench --json out/bench.json

# AddressSanitizer + UndefinedBehaviorSanitizer build and test run in build-sanitize/.
sanitize:
	@$(MAKE) test BUILD=build-sanitize CMAKE_FLAGS="-DPENUMBRA_WERROR=ON -DPENUMBRA_SANITIZE=ON -DCMAKE_BUILD_TYPE=Debug"

clean:
	@rm -rf $(BUILD) build-sanitize out
