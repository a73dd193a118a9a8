# ssaolab — the two README commands are `make run` and `make test`.
BUILD ?= build
JOBS  ?= $(shell nproc)
SCENE ?= builtin:showcase
OUT   ?= out

.PHONY: deps configure build run test clean

deps:
	@bash .ci/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Main job: the app. Without a display it renders the default scene headless into $(OUT)/.
run: build
	@$(BUILD)/app/ssaolab render --scene $(SCENE) --out $(OUT)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

clean:
	@rm -rf $(BUILD) $(OUT)
