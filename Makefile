# ssaolab — the two README commands are `make run` and `make test`.
BUILD ?= build
JOBS  ?= $(shell nproc)
SCENE ?= builtin:showcase
OUT   ?= out

.PHONY: deps configure build engine-modules run test docs screenshot goldens bench skips presets stress fuzz test-sanitize clean screen scaling peers explorer gpu-column user-twins layers temporal objective engines

deps:
	@bash .ci/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# The web engines' npm packages (three.js, N8AO, playwright-core) at the versions
# tools/peers/package-lock.json pins, into $(BUILD)/peers by npm ci once per lock: `ssaolab tune
# --engine`, `make peers` and the tests run them in Debian's chromium.
engine-modules: deps
	@bash .ci/engine-modules.sh $(BUILD)

# Main job: the app (a window when there is a display; otherwise a headless render of the
# default scene into ./out/, with a hint on how to get a window).
run: build
	@$(BUILD)/app/ssaolab

# The manual's generated pages (tests/cli/test_cli_docs.cpp fails when they are stale).
docs: build
	@$(BUILD)/app/ssaolab docs commands > docs/commands.md
	@$(BUILD)/app/ssaolab docs parameters > docs/parameters.md

# README screenshot, taken by the app itself under Xvfb.
screenshot: build
	@mkdir -p assets/screenshots
	@SSAOLAB_PRESET_DIR=$$(mktemp -d) xvfb-run -a -s "-screen 0 1920x1080x24" \
	  $(BUILD)/app/ssaolab view --size 1600x900 --frames 8 --screenshot assets/screenshots/explorer.png

# Every test, then a short libFuzzer run (60 s a target, ASan+UBSan, build-fuzz/) of the glTF
# loader, the settings parsers, bench merge's shard reader and the user technique header.
test: build engine-modules
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)
	@bash .ci/fuzz.sh build-fuzz $(SCENES)

# Golden AO images of the seed presets on builtin:showcase (tests/gl/test_golden.cpp compares).
GOLDEN_PRESETS = learnopengl seed000 crytek-sphere seed001 seed003 seed003-separable
goldens: build
	@for p in $(GOLDEN_PRESETS); do \
	  d=$$(mktemp -d) && $(BUILD)/app/ssaolab render --preset $$p --size 320x180 --timing-frames 1 --quiet --out $$d && \
	  cp $$d/ao.denoised.png assets/golden/showcase_$$p\_ao.png && rm -rf $$d && echo "golden: $$p"; done

# docs/benchmarks.md: reference rays/s and the time-against-error sweep on the shared scenes
# (640x360 on whatever GL the machine has; llvmpipe without a GPU; ~25 minutes on 2 cores;
# BENCH_SIZE=1280x720 for a larger frame).
SCENES ?= ../shared/scenes
bench: build
	@bash .ci/bench.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "Skipped work": each skip of unneeded work against the same frame without it
# (`ssaolab skips`; ~15 minutes on llvmpipe), then the page reassembled.
skips: build
	@bash .ci/skips.sh $(BUILD) $(SCENES)

presets: build
	@bash .ci/tune-presets.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "What the screen cannot see": every technique's error split against the
# screen-space oracle on every shared scene, and what a guard band or a second depth layer could
# close at best (`ssaolab bench`, `render --reference`), then the page reassembled.
screen: build
	@bash .ci/screen.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "Scaling": AO + denoise time against pixels and radius per technique, G-buffer
# time against triangles, reference time against rays and pixels, with each curve's exponent.
scaling: build
	@bash .ci/scaling.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "The web peers": three.js SSAOPass, SAOPass, GTAOPass and N8AO (from npm, pinned
# by tools/peers/package-lock.json) in Debian's Chromium on the same GL, against every shipped
# preset, in one run (~5 minutes on llvmpipe; needs Node.js with npm).
peers: build
	@bash .ci/peers.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "The explorer's frame times": still, drag and idle frames through the real UI,
# the start preset against learnopengl, per shared scene (~2 minutes on llvmpipe).
explorer: build
	@bash .ci/explorer.sh $(BUILD) $(SCENES)

# docs/benchmarks.md "The GPU column": from the folder .ci/gpu-run.sh filled on a machine with a GPU
# (GPU_RUN=DIR; GPU_NOTE: the machine line, e.g. the GPU, driver and host). Needs no GPU here.
gpu-column: build
	@bash .ci/gpu-column.sh $(BUILD) $(GPU_RUN) "$(GPU_NOTE)" $(SCENES)

# docs/bench/user-twins.md: the example user techniques (examples/techniques/) against their
# built-in twins on the same frames, the AO pass's time and its ratio (~5 minutes on llvmpipe).
user-twins: build
	@bash .ci/user-twins.sh $(BUILD) $(SCENES)

# docs/bench/layers.md: each bitmask preset and GTAO high with one depth layer and with two, the
# second peeled and in the single pass, and what nested parts need (~10 minutes on llvmpipe).
layers: build
	@bash .ci/layers.sh $(BUILD) $(SCENES)

# docs/bench/temporal.md: GTAO high and the bitmask with and without temporal accumulation along an
# orbit and a dolly on every shared scene, at each memory in motion and with the noise off (~5 minutes).
temporal: build
	@bash .ci/temporal.sh $(BUILD) $(SCENES)

# docs/bench/objective.md: per shared scene, the still and the motion answer at most the baseline's
# time among the shipped presets with and without temporal accumulation (~45 minutes on llvmpipe).
objective: build
	@bash .ci/objective.sh $(BUILD) $(SCENES)

# docs/bench/engines.md: every web engine tuned on every shared scene and a close-up city, at the
# view's radius: as shipped, lengths from R and tuned on held-out views, with time ratios (hours on
# llvmpipe; ENGINES=a,b and ENGINES_SIZE narrow it).
engines: build
	@bash .ci/engines.sh $(BUILD) $(SCENES)

# docs/stability.md: every technique under extreme projections, scales, placements, precisions and
# parameter limits (`ssaolab stress`).
stress: build
	@bash .ci/stress.sh $(BUILD) $(SCENES)

# The whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/);
# Mesa's own allocations that outlive eglTerminate are suppressed by library (.ci/lsan.supp; the
# sanitizer build keeps Mesa's driver mapped so LeakSanitizer can name it, renderer/gl/context.cpp).
test-sanitize: deps
	@cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSAOLAB_SANITIZE=ON >/dev/null
	@cmake --build build-asan -j $(JOBS)
	@bash .ci/engine-modules.sh build-asan
	@cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/.ci/lsan.supp:print_suppressions=0 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j $(JOBS)

# libFuzzer + ASan/UBSan on the glTF loader, the settings parsers, the shard reader and the user
# technique header (build-fuzz/, clang);
# FUZZ_SECONDS per target (60 by default; `FUZZ_SECONDS=3600 make fuzz` for a long run).
fuzz: configure
	@bash .ci/fuzz.sh build-fuzz $(SCENES)

clean:
	@rm -rf $(BUILD) $(OUT)
