# Two commands do everything on a fresh Debian 12 machine (as root):
#   make demo   installs what is missing, builds, renders every configuration into out/demo
#   make test   installs what is missing, builds, runs every test, then the sanitized share of them (sanitize-ci)
BUILD ?= build
JOBS ?= $(shell nproc)
# Line tables only (-g1) in the default RelWithDebInfo build: backtraces keep files and lines, and the build takes 347 s
# instead of 434 s on 2 cores (one run each, 2026-12-04); pass CMAKE_FLAGS to get full debug information.
CMAKE_FLAGS ?= -DPENUMBRA_WERROR=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
PENUMBRA = $(BUILD)/bin/penumbra

.PHONY: all deps configure build test demo bench bench-forest bench-loading bench-static shimmer-walk soak sanitize sanitize-ci tsan fuzz docs \
	format tidy sample-viewer-compare device-check clean

all: build

deps:
	@./scripts/install-deps.sh

# Ninja where a build folder is new (it starts a library's dependants before the library links, which keeps both of
# CI's cores busy: 10% off the sanitized build); a folder made earlier keeps its generator.
GENERATOR = $(if $(wildcard $(1)/CMakeCache.txt),,-G Ninja)

configure: deps
	@cmake -S . -B $(BUILD) $(call GENERATOR,$(BUILD)) $(CMAKE_FLAGS) --log-level=WARNING

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory sanitize-ci

# The parity report of every configuration for the mixed scene (directional, spot and point lights):
# out/demo/<configuration>/{pattern,lit,atlas,other-atlas,cascades}.png, atlas.exr, other-atlas.exr,
# out/demo/index.html, parity.json; then the four-light test scene through both backends.
demo: build
	@$(PENUMBRA) parity --scene mixed --out out/demo
	@$(PENUMBRA) render --backend vulkan,opengl --scene test --out out/demo/render/test.png \
		--atlas out/demo/render/test-atlas --debug cascades

bench: build
	@$(PENUMBRA) bench --suites draws,indirect,dispatches,shadows --json out/bench.json

# The forest's frame against the reference lit pass, 4 cascades of 2048^2 and of 4096^2 tiles, PCF 2x2, both backends
# in one run per tile size: out/bench-forest-2048.json, out/bench-forest-4096.json (the README's table).
bench-forest: build
	@for tiles in 2048 4096; do $(PENUMBRA) bench --scene forest --settings scripts/bench/forest-$$tiles-tiles.json \
		--backend vulkan,opengl --frames 10 --warmup 2 --json out/bench-forest-$$tiles.json || exit 1; done

# Loading a glTF file with a dozen 2048^2 PNG textures (the example writer's large-textures, written once into
# out/bench-loading/), then each backend's device, uploads, mip chains, pipelines and first frame: out/bench-loading.json
# (loadSeconds, firstFrameSeconds). Target: the first picture within 3 s on 2 cores.
bench-loading: build
	@[ -f out/bench-loading/large.gltf ] || $(BUILD)/tests/penumbra_write_example_gltf large-textures \
		out/bench-loading/large.gltf
	@$(PENUMBRA) bench --scene out/bench-loading/large.gltf --backend vulkan,opengl --size 64x64 --frames 1 \
		--warmup 0 --json out/bench-loading.json

# The long soak on both backends: SOAK_FRAMES (default 10000) frames of seeded viewer changes on SOAK_SCENE (default
# test), out/soak-<backend>.json with every checkpoint's resident memory and live RHI objects. The warm-up is long
# because the random changes reach the largest atlases (8192^2) and the last lit shader variants only after some
# thousand frames; resident memory rises to that plateau and stays (10 000 frames, both backends, 2026-12-02).
SOAK_FRAMES ?= 10000
SOAK_SCENE ?= test
soak: build
	@for backend in vulkan opengl; do $(PENUMBRA) soak --scene $(SOAK_SCENE) --backend $$backend --frames $(SOAK_FRAMES) \
		--size 160x90 --warmup 4000 --check-every 100 --json out/soak-$$backend.json || exit 1; done
# The town (64 static buildings, one dynamic ball) with every caster drawn every frame, with static maps kept
# (onChange) and from a bake, the realtime atlases drawing the ball alone: out/bench-static-<mode>.json.
# The shimmer measurement of depth-fitted cascades (docs/shadows-directional.md): a 100-frame camera walk through the
# single-light scene with the stable, close and depth fits, the changed ground points per frame, on both backends
# (about 6 minutes each on lavapipe; `make test` runs a 4-frame walk).
shimmer-walk: build
	@for configuration in vulkan opengl; do \
		$(BUILD)/tests/shadows_gpu/penumbra_shadow_gpu_tests --configuration $$configuration \
			--gtest_also_run_disabled_tests --gtest_filter='StableCascadesTest.DISABLED_Walk100Frames' || exit 1; done

bench-static: build
	@$(PENUMBRA) bake --scene town --settings scripts/bench/town-static.json --out out/bench-static-bake
	@for mode in everyFrame onChange baked; do \
		case $$mode in everyFrame) extra="--static-maps everyFrame";; \
		onChange) extra="--static-maps onChange --realtime-casters dynamic";; \
		baked) extra="--baked out/bench-static-bake --realtime-casters dynamic";; esac; \
		$(PENUMBRA) bench --scene town --settings scripts/bench/town-static.json $$extra --backend vulkan,opengl \
			--frames 10 --warmup 2 --json out/bench-static-$$mode.json || exit 1; done

# On a machine with a hardware Vulkan and EGL driver: the GPU tests of every configuration and the benchmarks (bench,
# bench-forest, the culling bench) in under 8 minutes, out/device-check/report.{md,json} with the device, the driver,
# every failure and each figure (scripts/device-check.sh; DEVICE_CHECK_BASELINE=report.json puts an earlier run's
# figures beside), and issue 44's culling targets on stdout.
# `make test` runs its quick mode on lavapipe and llvmpipe (ctest device-check.quick).
device-check: build
	@./scripts/device-check.sh --build $(BUILD) --out out/device-check \
		$(if $(DEVICE_CHECK_BASELINE),--baseline $(DEVICE_CHECK_BASELINE))

# AddressSanitizer + UndefinedBehaviorSanitizer build and test run of everything in build-sanitize/.
sanitize: deps
	@cmake -S . -B build-sanitize $(call GENERATOR,build-sanitize) -DPENUMBRA_WERROR=ON -DPENUMBRA_SANITIZE=ON \
		-DCMAKE_BUILD_TYPE=Debug --log-level=WARNING
	@cmake --build build-sanitize -j $(JOBS)
	@ctest --test-dir build-sanitize --output-on-failure -j $(JOBS)

# The share of `make sanitize` that `make test` runs, in build-sanitize-ci/: ASan + UBSan at -O0 with line tables
# (half the compile time of -O2 -g) over the code that reads untrusted input or plans on the CPU: the shadow planners'
# unit tests, the scene, glTF and ground-truth tests and the five fuzz corpora (glTF, settings, images, shaders, the
# command line). The GPU tests under the sanitizers (backends, renderer) are `make sanitize`'s: building the backends
# and the renderer a second time put `make test` over CI's 20 minutes.
SANITIZE_CI_TARGETS = penumbra_shadow_unit_tests penumbra_scene_tests penumbra_replay_gltf \
	penumbra_replay_shadow_settings penumbra_replay_image penumbra_replay_shader penumbra_replay_command_line
SANITIZE_CI_TESTS = ^(shadows|scene|fuzz)\.
sanitize-ci: deps
	@cmake -S . -B build-sanitize-ci $(call GENERATOR,build-sanitize-ci) -DPENUMBRA_WERROR=ON -DPENUMBRA_SANITIZE=ON \
		-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" --log-level=WARNING
	@cmake --build build-sanitize-ci -j $(JOBS) --target $(SANITIZE_CI_TARGETS)
	@ctest --test-dir build-sanitize-ci --output-on-failure -j $(JOBS) -R '$(SANITIZE_CI_TESTS)'

# ThreadSanitizer build in build-tsan/ of what the RHI's threading contract covers (rhi::Device: a device per thread,
# devices sharing no state): the threading tests. ASLR is off for the run (setarch -R): GCC 12's ThreadSanitizer
# cannot map its shadow memory under the wide mmap randomization of newer kernels.
tsan: deps
	@cmake -S . -B build-tsan $(call GENERATOR,build-tsan) -DPENUMBRA_WERROR=ON -DPENUMBRA_TSAN=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo --log-level=WARNING
	@cmake --build build-tsan -j $(JOBS) --target penumbra_threading_tests
	@TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$(CURDIR)/tests/threading/tsan.supp" setarch $$(uname -m) -R \
		ctest --test-dir build-tsan -R '^threading\.' --output-on-failure

# libFuzzer targets (tests/fuzz) with clang, ASan and UBSan in build-fuzz/, each run FUZZ_SECONDS (default 180) one
# after another: executions, coverage and crashes per target. FUZZ_TARGETS picks some (gltf shadow_settings
# command_line image shader).
FUZZ_SECONDS ?= 180
fuzz: deps
	@FUZZ_SECONDS=$(FUZZ_SECONDS) JOBS=$(JOBS) ./scripts/fuzz.sh $(FUZZ_TARGETS)

# The lit pictures of the glTF material scenes (tests/support's materials scene and scripts/sample-viewer/scenes.mjs's
# feature scenes) against the Khronos glTF Sample Viewer's, both backends: punctual light only in
# out/sample-viewer/results.{json,md} and <scene>/side-by-side.png, then with image-based lighting on both sides from
# one environment (scripts/sample-viewer/environment.mjs) in out/sample-viewer/ibl/. Installs chromium and the
# viewer's npm packages on demand (scripts/sample-viewer/compare.sh), not in `make deps`.
sample-viewer-compare: build
	@$(BUILD)/tests/penumbra_write_example_gltf materials out/sample-viewer/input/materials.glb
	@./scripts/sample-viewer/compare.sh --penumbra $(PENUMBRA) --out out/sample-viewer --scenes \
		out/sample-viewer/input/materials.glb
	@./scripts/sample-viewer/compare.sh --penumbra $(PENUMBRA) --out out/sample-viewer/ibl --ibl on --scenes \
		out/sample-viewer/input/materials.glb

# The API reference of the public headers and the guide (README.md, docs/) with Doxygen, warnings as errors:
# $(BUILD)/docs/html/index.html. The guide's generated regions (each command's --help, the settings reference) are
# rewritten from the built tool by scripts/docs/generate.sh; ctest's docs.* tests check the guide.
docs: deps
	@mkdir -p $(BUILD)/docs
	@PENUMBRA_DOCS_OUTPUT=$(BUILD)/docs doxygen docs/Doxyfile
	@echo "docs: $(BUILD)/docs/html/index.html"

# Formats every C++ source as .clang-format says (`make test` fails on any it would change).
format: deps
	@./scripts/check-format.sh --fix

# clang-tidy's small .clang-tidy set over the library and the tools, from the build's compile_commands.json.
tidy: deps
	@cmake -S . -B $(BUILD) $(CMAKE_FLAGS) -DCMAKE_EXPORT_COMPILE_COMMANDS=ON --log-level=WARNING
	@run-clang-tidy -quiet -p $(BUILD) '/(rhi|imageio|backends|shadows|scene|render|parity|apps)/'

clean:
	@rm -rf $(BUILD) build-sanitize build-sanitize-ci build-tsan build-fuzz out
