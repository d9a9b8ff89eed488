# The two commands: `make run` and `make test`. Both install what is missing
# (Debian packages, scripts/install-deps.sh), then build.
JOBS ?= $(shell nproc)
MAKEFLAGS += --no-print-directory

.PHONY: all deps build run test clean

all: build

deps:
	@scripts/install-deps.sh

build: deps
	@cmake --preset default >/dev/null
	@cmake --build build -j $(JOBS)

run: build
	@scripts/run.sh

test: build
	@scripts/install-deps.sh --test
	@scripts/test.sh

clean:
	rm -rf build build-dev build-asan build-fuzz
